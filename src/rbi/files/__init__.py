"""Every file rbi creates goes through this package (see docs/security.md, "Writing output").

- :mod:`rbi.files.output`: output paths (``--out``, ``--plot``, ...): checked before any work,
  written to a private temporary file in the same folder and renamed over the target only when
  the run succeeds.
- :mod:`rbi.files.safe`: the files kept beside an output (sidecars, partial files): opened
  without following links or blocking, checked to be regular files of this user, read with a
  size cap, created exclusively, shortened names that stay under 255 bytes.
- :mod:`rbi.files.lock`: one writer per output (an ``fcntl`` lock beside it).

It needs nothing of rbi but :mod:`rbi.errors` and :mod:`rbi.text`.
"""
