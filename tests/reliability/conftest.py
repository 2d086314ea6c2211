from tests.reliability.hostile import TRIED


def pytest_terminal_summary(terminalreporter):
    if TRIED:
        counts = ", ".join(f"{name} {count}" for name, count in sorted(TRIED.items()))
        terminalreporter.write_line(f"reliability: inputs tried: {sum(TRIED.values())} ({counts})")
