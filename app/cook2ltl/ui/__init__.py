"""The Textual app, the owner's surface over the whole pipeline. The core never imports this package."""


def run_app(recipe_path=None) -> None:
    """Open the app (imported here lazily, so `import cook2ltl.ui` stays cheap)."""
    from cook2ltl.ui.app import run_app as run

    run(recipe_path)
