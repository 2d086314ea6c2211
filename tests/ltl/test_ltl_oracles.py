"""Progression and the DFA against two independent LTLf implementations.

* flloat evaluates a formula on a trace directly;
* ltlf2dfa translates it to MONA's logic and MONA builds its minimal DFA.

Both are development-only dependencies (``pip install flloat ltlf2dfa``,
``apt-get install mona``); without them these tests are skipped. For every
(formula, trace) pair, every prefix of the trace is judged: our verdict must
say "holds" exactly when the oracle does, and SATISFIED / VIOLATED must
match MONA's DFA state (every / no continuation accepted).
"""

import random
import shutil
from collections.abc import Iterator

import pytest

from cook2ltl.ltl.automaton import build_dfa, powerset_alphabet
from cook2ltl.ltl.printer import to_spot
from cook2ltl.ltl.progress import Verdict, monitor
from tests.ltl.ltl_testkit import (
    FlloatOracle,
    MonaOracle,
    oracle_names,
    random_formula,
    random_trace,
    small_atoms,
    to_oracle_syntax,
)

FORMULAS = 1250
TRACES_PER_FORMULA = 8  # 10,000 (formula, trace) pairs
MAX_ATOMS = 4  # MONA blows up on many atoms; the issue allows up to 12
MAX_SIZE = 10  # operators per formula
MAX_TRACE = 8


def _cases(seed: int) -> Iterator[tuple]:
    """Deterministic random formulas, each with several random traces."""
    rng = random.Random(seed)
    for _ in range(FORMULAS):
        atoms = small_atoms(rng.randint(1, MAX_ATOMS))
        f = random_formula(rng, atoms, rng.randint(1, MAX_SIZE))
        traces = [random_trace(rng, atoms, rng.randint(1, MAX_TRACE)) for _ in range(TRACES_PER_FORMULA)]
        yield f, atoms, traces


def _show(f, trace) -> str:
    steps = " ; ".join(",".join(sorted(a.name for a in s)) or "-" for s in trace)
    return f"{to_spot(f)} on [{steps}]"


def test_progression_agrees_with_flloat():
    pytest.importorskip("flloat")
    oracle = FlloatOracle()
    pairs, disagreements = 0, []
    for f, atoms, traces in _cases(seed=11):
        names = oracle_names(atoms)
        text = to_oracle_syntax(f, names)
        for trace in traces:
            pairs += 1
            truths = oracle.prefix_truths(text, trace, names)
            ours = [r.verdict.holds for r in monitor(f, trace)]
            if ours != truths:
                disagreements.append(f"{_show(f, trace)}: ours {ours}, flloat {truths}")
    assert pairs >= 10_000
    assert disagreements[:5] == []


def _mona_or_skip() -> MonaOracle:
    pytest.importorskip("ltlf2dfa")
    if shutil.which("mona") is None:
        pytest.skip("MONA is not installed (apt-get install mona)")
    return MonaOracle()


def test_progression_and_dfa_agree_with_mona():
    oracle = _mona_or_skip()
    pairs, disagreements = 0, []
    for f, atoms, traces in _cases(seed=22):
        names = oracle_names(atoms)
        mona = oracle.dfa(to_oracle_syntax(f, names))
        for trace in traces:
            pairs += 1
            for k, (result, (accepted, state)) in enumerate(
                zip(monitor(f, trace), mona.prefix_acceptance(trace, names), strict=True), start=1
            ):
                future = mona.reaches(state)
                expected_final = {
                    Verdict.SATISFIED: future <= mona.accepting,
                    Verdict.VIOLATED: not future & mona.accepting,
                }
                if result.verdict.holds != accepted or not expected_final.get(result.verdict, True):
                    disagreements.append(f"{_show(f, trace[:k])}: ours {result.verdict}")
                    break
        ours = build_dfa(f, powerset_alphabet(atoms))
        if not _same_language(ours, mona, names):
            disagreements.append(f"{to_spot(f)}: DFA languages differ")
    assert pairs >= 10_000
    assert disagreements[:5] == []


def _same_language(ours, mona, names) -> bool:
    """Do both DFAs accept the same non-empty traces? (product search)"""
    mona_start = mona.edges[0][0][1]
    seen, todo = set(), [(ours.initial, mona_start)]
    while todo:
        q, m = todo.pop()
        for i, letter in enumerate(ours.alphabet):
            pair = (ours.delta[q][i], mona.successor(m, {names[a] for a in letter}))
            if (pair[0] in ours.accepting) != (pair[1] in mona.accepting):
                return False
            if pair not in seen:
                seen.add(pair)
                todo.append(pair)
    return True
