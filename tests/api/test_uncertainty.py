"""The uncertainty budget's table (`rbi.api.uncertainty`): each quantity lists its largest
contributions and one row for the rest, while JSON and CSV give every input."""

from __future__ import annotations

import rbi


def test_the_table_lists_the_largest_contributions_and_the_rest_in_one_row(tmp_path):
    """Before, every input had a row for every quantity: 20,000 point masses with ± printed
    300,000 rows (81 s, 1.7 GB)."""
    spec = tmp_path / "many.yaml"
    spec.write_text(
        "parts:\n"
        + "".join(
            f"  - {{name: p{i}, shape: point, mass: '{i + 1} ± 0.1', position: [{i}, 0, 0]}}\n"
            for i in range(30)
        )
    )
    budget = rbi.load(spec).uncertainty(of="mass")
    text = str(budget)
    assert text.count("parts.p") == 20 and "10 more inputs" in text
    assert len(budget.to_dict()["quantities"][0]["contributions"]) == 30
    assert len(budget.to_pandas()) == 30
