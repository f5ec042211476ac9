"""A sub-assembly whose file writes numbers with ±: the body reads them as their values and
says that their uncertainty is not propagated, rather than report u = 0 in silence."""

from __future__ import annotations

import rbi

SUB = 'parts: [{name: blk, shape: box, size: [0.01, "0.02 ± 0.0001", 0.005], mass: "0.01 ± 0.0001", center: [0, 0, 0]}]\n'


def test_a_sub_assemblys_plus_minus_is_named_in_a_warning(tmp_path):
    (tmp_path / "sub.yaml").write_text(SUB)
    (tmp_path / "plain.yaml").write_text(
        SUB.replace('"0.02 ± 0.0001"', "0.02").replace('"0.01 ± 0.0001"', "0.01")
    )
    top = tmp_path / "top.yaml"
    top.write_text(
        "parts: [{name: s, shape: assembly, file: sub.yaml}, {name: t, shape: assembly, file: plain.yaml}]\n"
    )
    body = rbi.load(top)
    assert body.mass == 0.02  # the values, 0.01 kg each
    (warning,) = [w for w in body.warnings if "±" in w]
    assert "parts[0] (s): file: sub.yaml" in warning and "not propagated" in warning
