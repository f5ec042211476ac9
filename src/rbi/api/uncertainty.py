"""The uncertainty budget of a body whose spec writes numbers with ± (`Body.uncertainty`,
``rbi uncertainty``): each quantity's value, standard uncertainty and coverage interval, and
every input's sensitivity, contribution and share, by the law of propagation (JCGM 100) or
Monte Carlo (JCGM 101)."""

from __future__ import annotations

from typing import Any

from rbi.memory import collector_paused
from rbi.reprs import Result, Rows, json_ready, plain
from rbi.spec.checks import UNITS
from rbi.spec.units import unit_labels
from rbi.text import number

TABLE_INPUTS = 20
"""Most inputs the table lists for one quantity, largest first (the rest share one row)."""


class UncertaintyBudget(Result):
    """The budget as ``rbi uncertainty --format json`` gives it (`to_dict`), its tables
    (``print``, rich, notebooks) and `to_pandas` (one row per quantity and input)."""

    def __init__(self, data: dict[str, Any]) -> None:
        self._data = data

    @json_ready
    def to_dict(self) -> dict[str, Any]:
        """The JSON object of ``rbi uncertainty`` (a new one each call; the contributions are
        made JSON-ready as they are built, the rest by :func:`rbi.reprs.plain`)."""
        with collector_paused():  # a budget of k inputs makes some 13 k dicts, none of them garbage
            quantities = [
                plain({k: v for k, v in q.items() if k != "contributions"})
                | {"contributions": q["contributions"].rows()}
                for q in self._data["quantities"]
            ]
        return plain(self._data | {"quantities": []}) | {"quantities": quantities}

    @property
    def quantities(self) -> list[dict[str, Any]]:
        """One entry per quantity: ``quantity``, ``value``, ``u``, ``interval``, ``coverage``,
        ``contributions`` (ranked, largest first)."""
        return self.to_dict()["quantities"]

    def csv_rows(self) -> list[dict[str, Any]]:
        """One flat row per quantity and input (the quantity's own numbers repeated)."""
        out = []
        for q in self.quantities:
            head = {"quantity": q["quantity"], "value": q["value"], "u": q["u"]}
            head |= {"low": q["interval"][0], "high": q["interval"][1], "coverage": q["coverage"]}
            if "linear" in q:
                head["linear_validated"] = q["linear"]["validated"]
            for c in q["contributions"] or [{}]:
                out.append(head | {f"input_{k}" if k in ("value", "u") else k: v for k, v in c.items()})
        return out

    def _quantities(self) -> Rows:
        """Each quantity's value, standard uncertainty and interval (Monte Carlo: the shortest,
        not symmetric about the mean), under the method and coverage."""
        d, rows = self._data, []
        labels = unit_labels(d["units"]["length"], d["units"]["mass"])
        for q in d["quantities"]:
            (low, high), name = q["interval"], q["quantity"]
            unit, half = labels[UNITS[name.split("[")[0]]], number((high - low) / 2, 2)
            interval = f"{number(low, 4)} … {number(high, 4)}" if d["samples"] else half
            rows.append((name, unit, number(q["value"], 5), number(q["u"], 2), interval))
        method = f"Monte Carlo, {d['samples']:,} draws" if d["samples"] else "linear"
        coverage = d["quantities"][0]["coverage"] if d["quantities"] else 0.95
        title = f"{d['name'] or 'body'} — uncertainty ({method}; {100 * coverage:g}% coverage)"
        columns = ("quantity", "unit", "value", "u", "interval" if d["samples"] else "± U")
        return Rows(title, columns, rows, left=2)

    def _validation(self) -> Rows:
        rows: list[tuple[str, ...]] = [
            (q["quantity"], " … ".join(number(end, 4) for end in q["linear"]["interval"]))
            + ("yes" if q["linear"]["validated"] else "NO",)
            for q in self._data["quantities"]
        ]
        columns = ("quantity", "linear interval", "linear ok")
        return Rows("Is the linear result validated? (JCGM 101 §8)", columns, rows)

    def _budget(self) -> Rows:
        rows: list[tuple[str, ...]] = []
        for q in self._data["quantities"]:  # one quantity's rows at a time
            found = [c for c in q["contributions"].rows() if c["contribution"] > 0]
            rows += [
                (q["quantity"], c["input"], number(c["sensitivity"], 4), f"{100 * c['share']:.1f}%")
                for c in found[:TABLE_INPUTS]
            ]
            if len(found) > TABLE_INPUTS:  # the rest in one row (JSON and CSV give each)
                rest = sum(c["share"] for c in found[TABLE_INPUTS:])
                rows.append(
                    (q["quantity"], f"{len(found) - TABLE_INPUTS:,} more inputs", "", f"{100 * rest:.1f}%")
                )
        estimated = self._data.get("estimated_sensitivities")
        title = "Contributions, largest first (share of the variance)" + (
            f"; ∂y/∂x by finite differences (~1e-9) for {', '.join(estimated)}" if estimated else ""
        )
        return Rows(title, ("quantity", "input", "∂y/∂x", "share"), rows, left=2)

    def rows(self) -> list[Rows]:
        """The quantities' table, then the contributions'."""
        validation = [self._validation()] if self._data["samples"] else []
        return [self._quantities(), *validation, self._budget()]
