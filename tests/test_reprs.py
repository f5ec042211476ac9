"""rbi.reprs: how results present themselves (the API's own tests, in tests/api, use public
names only)."""

from __future__ import annotations

import json

from tests.conftest import BODIES


def test_an_audit_is_not_walked_again(monkeypatch):
    # AuditReport.to_dict builds its JSON-ready links itself (millions of numbers for a large
    # robot): the base's plain() must not walk the whole report a second time
    import rbi.reprs

    walked = []
    real = rbi.reprs.plain
    monkeypatch.setattr(rbi.reprs, "plain", lambda value: walked.append(value) or real(value))
    data = rbi.audit(BODIES / "two_link_arm.urdf").to_dict()
    assert json.loads(json.dumps(data)) == data
    assert not any(isinstance(v, dict) and "links" in v for v in walked)
