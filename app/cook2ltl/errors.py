"""The one error type a user can act on: a message and a hint, caught at the CLI and UI edges."""


class UserError(Exception):
    """Something the user can fix: bad input, a missing model, a broken file."""

    def __init__(self, message: str, hint: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.hint = hint

    def __str__(self) -> str:
        return f"{self.message}\n  hint: {self.hint}" if self.hint else self.message


def require_utf8(value: str, what: str, hint: str) -> str:
    """The value, unless Python decoded it with surrogateescape (bytes that are not UTF-8, from argv or the
    environment): nothing downstream (sqlite, files, the terminal) can encode those lone surrogates."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        shown = value.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
        raise UserError(f"{what} {shown!r} is not UTF-8 text.", hint) from None
    return value
