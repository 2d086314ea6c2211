"""Which library keys translations running side by side are asking the model for, so that each is asked once."""

from __future__ import annotations

import threading
from collections.abc import Hashable


class Claims:
    """A key taken by one translation until it gives it back; another asking for it waits meanwhile."""

    def __init__(self) -> None:
        self._taken: set[Hashable] = set()
        self._changed = threading.Condition()

    def take(self, key: Hashable) -> bool:
        """True when the key is now this caller's; False after waiting for another's to be given back (the
        caller then looks in the library again, where the other has left its entry)."""
        with self._changed:
            if key not in self._taken:
                self._taken.add(key)
                return True
            self._changed.wait_for(lambda: key not in self._taken)
            return False

    def give_back(self, key: Hashable) -> None:
        with self._changed:
            self._taken.discard(key)
            self._changed.notify_all()
