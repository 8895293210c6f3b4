"""Objects that own one library handle (a photometry, scene or solution).

The library frees a handle once, when no call uses it (its headers say so:
"release one only when no call uses it"). A Python program may close an
object in one thread while another thread's call uses it (a solve running
on its own thread, intensity() over a large array, write()): every call
borrows the handle for its duration, and close() while a call borrows it
only marks the object closed; the last borrower frees the handle.
"""

from __future__ import annotations

import threading
from contextlib import contextmanager
from typing import Iterator, Optional

from ._capi import lib
from .errors import UsageError


class Owned:
    """Owns a handle, freed by the library function named `_release` on
    close(), at the end of a `with` block, or when collected, and never
    while a call borrows it. `_what` names the object in the message of a
    use after close."""

    _release = ""
    _what = "object"
    _handle: Optional[int] = None

    def _own(self, handle: int) -> None:
        """Take ownership of handle (from the constructor)."""
        self._guard = threading.Lock()
        self._borrowers = 0
        self._closed = False
        self._handle = handle

    def _acquire(self) -> int:
        """Borrow the handle until _unacquire(); UsageError once closed."""
        with self._guard:
            if self._closed or self._handle is None:
                raise UsageError(f"{self._what}: closed")
            self._borrowers += 1
            return self._handle

    def _unacquire(self) -> None:
        """End a borrow; the last borrower of a closed object frees it."""
        with self._guard:
            self._borrowers -= 1
            handle = self._take_if_unused()
        self._free(handle)

    @contextmanager
    def _use(self) -> Iterator[int]:
        """The handle, borrowed for a `with` block."""
        handle = self._acquire()
        try:
            yield handle
        finally:
            self._unacquire()

    def _take_if_unused(self) -> Optional[int]:
        """The handle, taken from self, when closed and unborrowed (the guard held)."""
        if not self._closed or self._borrowers > 0:
            return None
        handle, self._handle = self._handle, None
        return handle

    def _free(self, handle: Optional[int]) -> None:
        if handle is not None:
            getattr(lib, self._release)(handle)

    @property
    def closed(self) -> bool:
        """True once close() was called (the library's object is freed as
        soon as no call uses it)."""
        return getattr(self, "_closed", True)

    def close(self) -> None:
        """Free the library's object (collection does it too). Calls under
        way in other threads finish first: the object is freed when the last
        of them ends; new calls raise UsageError."""
        guard = getattr(self, "_guard", None)
        if guard is None:  # (a constructor that failed before owning anything)
            return
        with guard:
            self._closed = True
            handle = self._take_if_unused()
        self._free(handle)

    def __del__(self):
        try:
            self.close()
        except Exception:  # (at interpreter exit the library may be gone first)
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()
