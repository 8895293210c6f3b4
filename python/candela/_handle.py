"""Objects that own one library handle (a photometry, scene or solution)."""

from __future__ import annotations

from typing import Optional

from ._capi import lib
from .errors import UsageError


class Owned:
    """Owns `_handle`, freed by the library function named `_release` on
    close(), at the end of a `with` block, or when collected. `_what` names
    the object in the message of a use after close."""

    _release = ""
    _what = "object"
    _handle: Optional[int] = None

    def _live(self) -> int:
        """The handle, or UsageError once closed."""
        if self._handle is None:
            raise UsageError(f"{self._what}: closed")
        return self._handle

    def close(self) -> None:
        """Free the library's object now (collection does it too)."""
        handle, self._handle = self._handle, None
        if handle is not None:
            getattr(lib, self._release)(handle)

    def __del__(self):
        try:
            self.close()
        except Exception:  # (at interpreter exit the library may be gone first)
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()
