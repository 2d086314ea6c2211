"""``cook2ltl ltl``: read a formula, or follow it step by step over a trace.

    cook2ltl ltl parse 'F(pick_up(knife) & F "slice(tomato, knife)")'
    cook2ltl ltl progress 'F(a & F b)' a - 'b; cold(apple)' --json

A STEP lists the atoms true in it separated by ``;`` (``-`` for none).
"""

from __future__ import annotations

from typing import Annotated

import typer
from rich.table import Table
from rich.text import Text

from cook2ltl.errors import UserError
from cook2ltl.ltl.ast import Atom, Formula
from cook2ltl.ltl.parser import LTLSyntaxError, parse
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.ltl.progress import Verdict, monitor, verdict
from cook2ltl.text_safety import json_text, literal, terminal

ltl_app = typer.Typer(
    help="Parse LTLf formulas and follow them step by step over a trace.",
    no_args_is_help=True,
)

_VERDICT_STYLE = {
    Verdict.SATISFIED: "bold green",
    Verdict.VIOLATED: "bold red",
    Verdict.PRESUMABLY_TRUE: "green",
    Verdict.PRESUMABLY_FALSE: "yellow",
}

JsonOption = Annotated[bool, typer.Option("--json", help="Print plain JSON to stdout.")]


_SYNTAX_HINT = (
    "write F G X X[!] U R W M ! & | -> <-> (or ◇ □ ○ 𝒰 ∧ ∨ ¬ →), "
    'atoms as pick_up(knife) or "slice(tomato, knife)"'
)


def _read_formula(text: str) -> Formula:
    try:
        return parse(text)
    except LTLSyntaxError as err:
        raise UserError(f"not a formula: {err}", _SYNTAX_HINT) from None


def read_step(text: str) -> frozenset[Atom]:
    """``"pick_up(knife); cold(apple)"`` -> those two atoms; ``"-"`` -> none."""
    atoms = set()
    for part in text.split(";"):
        part = part.strip()
        if part in ("", "-"):
            continue
        atom = parse(part)
        if not isinstance(atom, Atom):
            raise ValueError(f"{part!r} is not an atom")
        atoms.add(atom)
    return frozenset(atoms)


def _atom_list(atoms) -> list[str]:
    return [a.text for a in sorted(atoms, key=lambda a: a.key)]


@ltl_app.command("parse")
def parse_command(
    formula: Annotated[str, typer.Argument(help="The formula, in Spot ASCII or Unicode syntax.")],
    as_json: JsonOption = False,
) -> None:
    """Print the formula in both syntaxes, and its atoms."""
    f = _read_formula(formula)
    if as_json:
        typer.echo(json_text({"unicode": to_unicode(f), "spot": to_spot(f), "atoms": _atom_list(f.atoms)}))
        return
    table = Table(show_header=False, box=None)
    table.add_row(literal("Unicode", style="bold"), literal(to_unicode(f)))
    table.add_row(literal("Spot", style="bold"), literal(to_spot(f)))
    table.add_row(literal("Atoms", style="bold"), literal(", ".join(_atom_list(f.atoms)) or "(none)"))
    terminal().print(table)


@ltl_app.command("progress")
def progress_command(
    formula: Annotated[str, typer.Argument(help="The formula, in Spot ASCII or Unicode syntax.")],
    steps: Annotated[
        list[str] | None,
        typer.Argument(help="Each step: the atoms true in it, separated by ';', or '-' for none."),
    ] = None,
    as_json: JsonOption = False,
) -> None:
    """Show the remaining obligation and the verdict after every step."""
    f = _read_formula(formula)
    trace = []
    for number, text in enumerate(steps or [], start=1):
        try:
            trace.append(read_step(text))
        except ValueError as err:  # LTLSyntaxError is a ValueError
            raise UserError(
                f"step {number} is not a list of atoms: {err}",
                "separate the atoms true in a step with ';', or write '-' for none",
            ) from None
    results = list(monitor(f, trace))
    final = results[-1].verdict if results else verdict(f)
    if as_json:
        payload = {
            "formula": to_spot(f),
            "steps": [
                {
                    "index": r.index,
                    "atoms": _atom_list(r.step),
                    "remaining": to_spot(r.remaining),
                    "remaining_unicode": to_unicode(r.remaining),
                    "verdict": r.verdict.value,
                }
                for r in results
            ],
            "verdict": final.value,
        }
        typer.echo(json_text(payload))
        return
    table = Table("#", "step", "remaining obligation", "verdict")
    table.add_row("0", literal("(start)", style="dim"), literal(to_unicode(f)), _verdict_text(verdict(f)))
    for r in results:
        shown = "; ".join(_atom_list(r.step)) or "-"
        table.add_row(str(r.index), literal(shown), literal(to_unicode(r.remaining)), _verdict_text(r.verdict))
    console = terminal()
    console.print(table)
    console.print(Text.assemble("Trace as a whole: ", _verdict_text(final)))


def _verdict_text(v: Verdict) -> Text:
    return Text(v.value.replace("_", " "), style=_VERDICT_STYLE[v])
