"""Translators built from a request, the same for the command line, the app, rollouts and the benchmarks; and
the one rule for whether a new reduction is run in the kitchen before it is cached."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass
from pathlib import Path

from cook2ltl import paths
from cook2ltl.domain.actions import PrimitiveSet
from cook2ltl.domain.settings_file import load_settings
from cook2ltl.execution.kitchen_check import KitchenValidator, unsupported
from cook2ltl.library.store import Library
from cook2ltl.pipeline.records import Variant
from cook2ltl.pipeline.translator import Translator
from cook2ltl.reduce.llm import LanguageModel
from cook2ltl.reduce.reduction import ReductionSettings
from cook2ltl.reduce.validation import PlanValidator
from cook2ltl.world.kitchens import grounding


@dataclass(frozen=True)
class TranslateOptions:
    variant: Variant = Variant.AR_LIBRARY
    settings: ReductionSettings = ReductionSettings()
    check: bool | None = None  # run new reductions in the kitchen: None where it helps (see `checks_in_kitchen`)
    repairs: int | None = None  # times a plan the kitchen refuses goes back to the model; None: the settings'
    approved_only: bool = False  # lab mode: reuse approved library entries only
    ground: bool = True  # decode, check and complete every plan in the primitive set's world model
    reuse: bool = True  # reuse a library entry across verbs of one table row and signatures (False: exact keys)


def checks_in_kitchen(primitives: PrimitiveSet, check: bool | None, variant: Variant, grounded: bool,
                      notice: Callable[[str], None]) -> bool:
    """Whether new reductions run in the THOR kitchen before they are cached. Asked for (`check` True), always:
    a set the kitchen cannot run is then an error (KitchenValidator says so). By default (None), only where
    a reduction is cached (AR+𝔸), and not for a set whose world has a kitchen of its own while the world model
    judges the plans; a set with actions THOR has no stand-in for is then skipped with a notice."""
    if check is not None:
        return check
    if variant != Variant.AR_LIBRARY or (grounded and primitives.world.kitchen is not None):
        return False
    missing = unsupported(primitives)
    if missing:
        notice(f"Not checking new reductions: the kitchen has no action for {', '.join(missing)}.")
    return not missing


def build_translator(primitives: PrimitiveSet, model: LanguageModel, library: Library | None,
                     options: TranslateOptions, kitchen_check: Callable[[PrimitiveSet], PlanValidator],
                     notice: Callable[[str], None]) -> Translator:
    """The translator `options` describe. `library` is used by AR+𝔸 only; `kitchen_check` gives the validator
    when the rule wants one (the caller owns and closes it)."""
    world = grounding(primitives) if options.ground else None
    checking = checks_in_kitchen(primitives, options.check, options.variant, world is not None, notice)
    repairs = load_settings().translate.repairs if options.repairs is None else options.repairs
    return Translator(primitives, model, library if options.variant == Variant.AR_LIBRARY else None,
                      options.variant, options.settings, kitchen_check(primitives) if checking else None, repairs,
                      options.approved_only, world, options.reuse)


@contextmanager
def open_translator(primitives: PrimitiveSet, model: LanguageModel, library: Path | None,
                    options: TranslateOptions, notice: Callable[[str], None]) -> Iterator[Translator]:
    """A translator with its own library file (default: the user's; opened for AR+𝔸 only) and kitchen, both
    closed on exit."""
    with ExitStack() as closing:
        store = None
        if options.variant == Variant.AR_LIBRARY:
            store = Library(library or paths.library_file())
            closing.callback(store.close)

        def kitchen_check(checked: PrimitiveSet) -> PlanValidator:
            return closing.enter_context(KitchenValidator(checked))

        yield build_translator(primitives, model, store, options, kitchen_check, notice)
