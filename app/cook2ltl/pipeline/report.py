"""A translation as text, the same in the terminal and in a file the app writes: per step its frames,
reductions, kitchen checks and formula, then the counts and the two rates."""

from __future__ import annotations

from rich.console import Console

from cook2ltl.domain.actions import Source
from cook2ltl.ltl.printer import to_spot, to_unicode
from cook2ltl.pipeline.rates import rates
from cook2ltl.pipeline.records import Translation
from cook2ltl.reduce.validation import CheckStatus
from cook2ltl.text_safety import literal, styled

SOURCE_STYLE = {Source.PRIMITIVE: "green", Source.LIBRARY: "cyan", Source.LLM: "magenta", Source.WORLD: "dim"}


def show(translation: Translation, console: Console) -> None:
    console.print(literal(f"primitives {translation.primitives} · variant {translation.variant.value} · "
                          f"model {translation.model}", "dim"))
    for reason in translation.skipped_verbs:
        console.print(literal(f"! {reason}", "yellow"), highlight=False)
    for step in translation.steps:
        console.print(styled((f"{step.step.index + 1:>3}. ", "dim"), step.step.sentence.text))
        for index, frame in enumerate(step.step.frames):
            console.print(literal("      " + frame.signature(), "dim"))
            for result in (r for r in step.actions if r.frame_index == index):
                _show_reduction(result, console)
        console.print(styled(("      φ = ", "dim"), (to_unicode(step.formula), "yellow")), soft_wrap=True)
        console.print(literal("          " + to_spot(step.formula), "dim"), soft_wrap=True)
        for problem in step.problems:
            console.print(styled("      ", ("!", "bold red"), " ", problem), highlight=False)
    stats = translation.stats
    console.print(literal(
        f"{stats.actions} actions: {stats.primitive} primitive, {stats.library_hits} from the library"
        f"{f' ({stats.cross_reuses} reused across verbs or signatures)' if stats.cross_reuses else ''}, "
        f"{stats.llm_calls} LLM calls ({stats.prompt_tokens} prompt + {stats.completion_tokens} completion tokens, "
        f"{stats.llm_seconds:.1f} s); {stats.new_entries} new library entries; {stats.seconds:.1f} s in all", "dim"))
    console.print(literal(rates_line(translation), "dim"), highlight=False, soft_wrap=True)


def rates_line(translation: Translation) -> str:
    counts, stats = rates(translation), translation.stats
    line = "executability " + (f"{counts.executability:.0%} ({counts.admissible_lines} of {counts.written_lines} "
                               f"lines the model wrote are admissible)" if counts.executability is not None else "-")
    if counts.validated_rate is None:
        return line + "; validated -" + ("" if translation.validating else " (not validating)")
    return (line + f"; validated {counts.validated_rate:.0%} ({stats.validated} of {counts.new_reductions} new "
            f"reductions run in the kitchen, {stats.repaired} after repair; {stats.repair_calls} repair calls; "
            f"{stats.checked} checked)")


def _show_reduction(result, console: Console) -> None:
    reduction = result.reduction
    entry = f" #{reduction.entry_id}" if reduction.entry_id is not None else ""
    console.print(styled("        → ", (reduction.action.text(), "bold"),
                         (f"  {reduction.source.value}{entry}", SOURCE_STYLE[reduction.source])))
    if result.reuse is not None:
        console.print(literal(f"            reused: {result.reuse.text()}", SOURCE_STYLE[Source.LIBRARY]),
                      highlight=False, soft_wrap=True)
    if reduction.source != Source.PRIMITIVE:
        for call in reduction.body:
            console.print(literal(f"            {call.text()}"), highlight=False)
    for dropped in reduction.dropped:
        console.print(styled("            ", (f"✗ {dropped}", "red"), " ", ("(not admissible, dropped)", "dim")),
                      highlight=False)
    check = result.validation
    if check is not None:
        repaired = f", after {len(result.attempts)} repair{'s' if len(result.attempts) > 1 else ''}" if result.attempts else ""
        style = "green" if check.passed else "yellow" if not check.checked else "red"
        console.print(styled("            ", (f"kitchen check: {check.status}", style), " ",
                             (f"({check.scene or 'no scene'}{repaired})", "dim")), highlight=False)
        for message in check.messages():
            console.print(literal(f"            ! {message}", style), highlight=False)
    if result.entry_validation == CheckStatus.FAILED:
        console.print(literal("            kitchen check when learnt: failed", "red"), highlight=False)
        for message in result.entry_problems:
            console.print(literal(f"            ! {message}", "red"), highlight=False)
