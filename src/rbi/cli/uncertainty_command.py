"""`rbi uncertainty`: the uncertainty budget of the numbers a spec writes with ± (JCGM 100, 101)."""

from __future__ import annotations

import rbi
from rbi.cli.each_file import FileReport, report_each
from rbi.cli.options import FORMAT, OutputFormat, SpecFiles, command, option


@command(
    option(
        list[str] | None,
        "--of",
        metavar="QUANTITY",
        help="A quantity as a JSON path of rbi inertia/principal: mass, center_of_mass[0], inertia[0][2], "
        "moments[1]; center_of_mass alone: its 3 entries (repeat for several). Default: mass, centre of mass, inertia about it, principal moments.",
    ),
    option(str, "--method", metavar="linear|monte-carlo", help="Law of propagation or Monte Carlo."),
    option(int, "--samples", metavar="N", help="Monte Carlo draws."),
    option(int | None, "--seed", metavar="S", help="Seed of the draws."),
    option(float, "--coverage", metavar="P", help="Coverage probability."),
    FORMAT,
    api=rbi.Body.uncertainty,
)
def uncertainty(files: SpecFiles, *, format: OutputFormat, **settings) -> int:
    """The uncertainty budget: each quantity's value, standard uncertainty and interval, and
    every ± input's sensitivity, contribution and share, largest first.

    \b
    Examples:
      rbi uncertainty top_bolted_toleranced.yaml
      rbi uncertainty top_bolted_toleranced.yaml --of "inertia[0][2]"
      rbi uncertainty top_bolted_toleranced.yaml --method monte-carlo --seed 1
    """

    def report(file: str) -> FileReport:
        return FileReport(rbi.load(file).uncertainty(**settings))

    return report_each(files, report, format.value)
