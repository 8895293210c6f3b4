"""The exceptions of the candela package: one per status of the library.

Every error the library reports becomes a CandelaError subclass carrying the
library's own message, which names the input (the file and line, or the JSON
path of a scene) and what was expected.
"""

from __future__ import annotations

from . import _capi


class CandelaError(Exception):
    """A call into libcandela failed. `status` is the library's status code
    (1 bad input, 2 usage, 3 internal, 4 cancelled), `message` its message."""

    status: int = _capi.CDL_ERR_INTERNAL

    def __init__(self, message: str, status: int | None = None):
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status


class InputError(CandelaError, ValueError):
    """Bad input: a photometric file, scene or value the caller gave
    (the message names the file and line, or the JSON path)."""

    status = _capi.CDL_ERR_INPUT


class UsageError(CandelaError, ValueError):
    """The call itself was wrong: an option out of range or of the wrong kind."""

    status = _capi.CDL_ERR_USAGE


class InternalError(CandelaError, RuntimeError):
    """An internal or resource failure: memory, I/O, a library underneath."""

    status = _capi.CDL_ERR_INTERNAL


class Cancelled(CandelaError):
    """A solve was cancelled by its caller (a `cancel` event was set, or
    SolveJob.cancel was called)."""

    status = _capi.CDL_ERR_CANCELLED


_BY_STATUS = {
    _capi.CDL_ERR_INPUT: InputError,
    _capi.CDL_ERR_USAGE: UsageError,
    _capi.CDL_ERR_INTERNAL: InternalError,
    _capi.CDL_ERR_CANCELLED: Cancelled,
}


def from_status(status: int, err: _capi.cdl_error) -> CandelaError:
    """The exception for a failed call's status and the message it left in err."""
    message = _capi.text(err.message)  # (a char array field reads as bytes up to its NUL)
    if not message:
        message = _capi.text(_capi.lib.cdl_status_name(status))
    cls = _BY_STATUS.get(status, CandelaError)
    return cls(message, status)


def check(status: int, err: _capi.cdl_error) -> None:
    """Raise the exception for status unless it is CDL_OK."""
    if status != _capi.CDL_OK:
        raise from_status(status, err)
