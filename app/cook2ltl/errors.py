"""The one error type a user can act on: a message and a hint, caught at the CLI and UI edges."""


class UserError(Exception):
    """Something the user can fix: bad input, a missing model, a broken file."""

    def __init__(self, message: str, hint: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.hint = hint

    def __str__(self) -> str:
        return f"{self.message}\n  hint: {self.hint}" if self.hint else self.message
