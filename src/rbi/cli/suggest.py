""" "Did you mean …?": the nearest valid name for a misspelt command or option."""

from __future__ import annotations

import difflib
from collections.abc import Iterable

from typer._click.exceptions import NoSuchOption


def nearest(name: str, valid: Iterable[str]) -> str | None:
    """The valid name closest to ``name`` (difflib's ratio of at least 0.6), or None."""
    found = difflib.get_close_matches(name, list(valid), n=1, cutoff=0.6)
    return found[0] if found else None


def did_you_mean(name: str, valid: Iterable[str]) -> str:
    """`` (did you mean 'cylinder'?)`` for the nearest valid name, or nothing."""
    hint = nearest(name, valid)
    return f" (did you mean {hint}?)" if hint else ""


def usage_message(error) -> str:
    """The one-line message for a click usage error: an unknown option names the nearest of the
    command's own options (``no such option: --abuot (did you mean --about?)``)."""

    if isinstance(error, NoSuchOption) and error.ctx is not None:
        options = [
            name
            for param in error.ctx.command.params
            for name in (*param.opts, *param.secondary_opts)
            if name.startswith("-")
        ]
        return f"no such option: {error.option_name}{did_you_mean(error.option_name, options)}"
    return error.format_message()
