"""Many recipes translated side by side: one thread per translator, so their model calls can be decoded in one batch
(`cook2ltl.reduce.batched`) while the others check plans in the world model.

Each translator has its own connection to the library (a SQLite connection belongs to its thread); they share
the model, the world and `Claims`, so a key two recipes need at once goes to the model once: the second waits
and then finds the first one's entry. Which recipe teaches the library a verb depends on timing, so the
library, and through it the plans, may differ between runs, as with any other order of the recipes.
"""

from __future__ import annotations

import queue
import threading
from collections.abc import Iterator, Sequence
from dataclasses import replace

from cook2ltl.domain.recipe import ParsedRecipe
from cook2ltl.pipeline.claims import Claims
from cook2ltl.pipeline.records import Translation, TranslationFinished
from cook2ltl.pipeline.translator import Translator, translate


def translate_side_by_side(recipes: Sequence[ParsedRecipe], translators: Sequence[Translator],
                           cancel: threading.Event | None = None) -> Iterator[tuple[int, Translation]]:
    """(index, translation) of each recipe as it is done, recipes taken in order by the first idle translator.
    A failure stops the others after their current recipe and is raised here."""
    cancel = cancel or threading.Event()
    claims = Claims()
    next_index = iter(range(len(recipes)))
    taking = threading.Lock()
    done: queue.Queue = queue.Queue()

    def work(translator: Translator) -> None:
        try:
            while not cancel.is_set():
                with taking:
                    index = next(next_index, None)
                if index is None:
                    return
                events = translate(recipes[index], translator, cancel)
                finished = [e.translation for e in events if isinstance(e, TranslationFinished)]
                if finished:
                    done.put((index, finished[0]))
        except BaseException as error:  # handed to the caller's thread, which raises it
            done.put((None, error))
        finally:
            done.put((None, None))

    workers = [threading.Thread(target=work, args=(replace(t, claims=claims),), daemon=True) for t in translators]
    for worker in workers:
        worker.start()
    running, failure = len(workers), None
    try:
        while running:
            index, result = done.get()
            if index is not None:
                yield index, result
            elif result is None:
                running -= 1
            elif failure is None:
                failure = result
                cancel.set()
    finally:
        if running:  # a caller that stops early stops the workers too
            cancel.set()
        for worker in workers:
            worker.join()
    if failure is not None:
        raise failure
