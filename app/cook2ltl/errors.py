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
        # bytes from argv come back as they were; a lone surrogate of any other kind is written as an escape
        shown = value.encode("utf-8", "surrogateescape" if _only_escaped_bytes(value) else "backslashreplace")
        shown = shown.decode("utf-8", "replace")
        raise UserError(f"{what} {shown!r} is not UTF-8 text.", hint) from None
    return value


def _only_escaped_bytes(value: str) -> bool:
    """Whether every surrogate in `value` is one surrogateescape made of a byte (U+DC80 to U+DCFF)."""
    return all(not "\ud800" <= char <= "\udfff" or "\udc80" <= char <= "\udcff" for char in value)
