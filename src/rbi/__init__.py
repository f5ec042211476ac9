"""rbi: a command-line rigid-body calculator.

Layers (each imports only those below it):
``core`` (pure numpy physics) <- ``spec`` (YAML, units, validation) <- ``sim`` (time evolution)
<- ``cli`` (typer commands and rendering).
"""

__version__ = "0.1.0"
