"""Tests of rbi audit: each runs in its own temporary folder (MuJoCo writes MUJOCO_LOG.TXT into
the working folder when a model warns, as settotalmass does)."""

import pytest


@pytest.fixture(autouse=True)
def _in_a_temporary_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
