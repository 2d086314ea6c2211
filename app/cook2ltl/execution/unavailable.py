"""The one failure every kitchen start and step can end in, said as what it is."""

from __future__ import annotations

from cook2ltl.errors import UserError


class KitchenUnavailable(UserError):
    """No kitchen could be started; the message says why, starting "THOR unavailable:"."""

    def __init__(self, reason: str) -> None:
        super().__init__(f"THOR unavailable: {reason}")
        self.reason = reason
