"""rbi.names lists the public names once: ``rbi.__all__`` and ``rbi.api.__all__`` are read from
it, and every name it lists is served."""

from __future__ import annotations

import rbi
import rbi.api
from rbi.names import PUBLIC


def test_each_list_is_read_from_the_one_source():
    assert rbi.__all__ == [*PUBLIC, "__version__"]
    assert rbi.api.__all__ == list(PUBLIC)
    assert len(set(PUBLIC)) == len(PUBLIC)  # none twice


def test_every_listed_name_is_served_by_the_api_and_the_public_ones_by_rbi():
    for name in PUBLIC:
        assert getattr(rbi, name) is getattr(rbi.api, name), name
