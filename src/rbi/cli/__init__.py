"""The command-line layer: parse options, call the core, render. No physics here."""
