"""How a command ends on bad input or an internal error: one line on stderr and the
exit code (docs/exit_codes.md). Shared by gyro_cli/cli.py and the commands it loads
only when they run (commands/others.py)."""

from __future__ import annotations

import os
import sys
from typing import NoReturn

import click

from ..core.errors import InputError, internal_message

INTERNAL = 3  # exit code: gyro failed on a file (a bug), not the input


def fail(error: InputError | str) -> NoReturn:
    """Print one line on stderr and exit 2."""
    click.echo(f"gyro: {error}", err=True)
    sys.exit(2)


def internal(file: str | None, error: BaseException) -> None:
    """Report an unexpected exception on one line (traceback with GYRO_DEBUG=1)."""
    click.echo(f"gyro: {internal_message(file, error)}", err=True)
    if os.environ.get("GYRO_DEBUG"):
        import traceback

        traceback.print_exception(error)


def outputs_apart(inputs: list[str] | tuple[str, ...],
                   identities: dict[str, tuple[int, int]] | None = None,
                   **outputs: str | None) -> None:
    """Exit 2 with one line if an output file (by option name) is empty or would replace
    one of the command's inputs (core/files.py: refuse_input_as_output; ``identities``
    as it takes them)."""
    from ..core.files import refuse_input_as_output

    for option, name in outputs.items():
        if name is not None:
            try:
                refuse_input_as_output(name, inputs, option="--" + option.replace("_", "-"),
                                       identities=identities)
            except InputError as err:
                fail(err)
