"""Pure numerical core: plain numpy arrays and floats, no YAML, pydantic or terminal.

Units are whatever consistent set the caller uses (rbi passes the spec file's own units);
frames and reference points are stated in each function's docstring.
"""
