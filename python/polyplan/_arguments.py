"""How the Python half checks and names the arguments it passes on: a value shown in a message,
and a file's or folder's path. The compiled half checks what it reads itself (exact_values.cpp)."""

import os

from ._polyplan import InputError


def shown(value, width=300):
    """repr(value) for a message, cut at `width` characters; an integer too long to write (str()
    refuses 4300 digits) named by its bits."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 64:
        return f"(an integer of {value.bit_length()} bits)"
    text = repr(value)
    return text if len(text) <= width else text[:width - 3] + "..."


def path(value, what, kind="folder", utf8=True):
    """A file's or folder's path: a non-empty str, or an os.PathLike giving one; without NUL (the
    file system would read or write the path cut short there) and, for the compiled half
    (utf8=True), in UTF-8 (a name of bytes that are not UTF-8, decoded with surrogates, cannot be
    passed on; Python's own file functions take it). InputError naming `what`."""
    if isinstance(value, os.PathLike):
        try:
            value = os.fspath(value)
        except TypeError as e:
            raise InputError(f"{what}: {e}") from None
    if not isinstance(value, str):
        raise InputError(f"{what}: expected a {kind}'s path (a str or a pathlib.Path), got {type(value).__name__}")
    if not value:
        raise InputError(f"{what}: expected a {kind}'s path, got an empty str")
    if "\0" in value:
        raise InputError(f"{what}: {shown(value)}: a path cannot hold a NUL character")
    if utf8:
        try:
            value.encode("utf-8")
        except UnicodeEncodeError:
            raise InputError(f"{what}: {shown(value)}: not UTF-8 (a name of bytes the file system did not decode; "
                             "rename the file or folder)") from None
    return value
