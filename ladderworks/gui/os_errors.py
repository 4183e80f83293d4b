"""Why the operating system refused a file, in the UI language (Python's strerror is English)."""

from __future__ import annotations

import errno

from PySide6.QtCore import QCoreApplication

translate = QCoreApplication.translate


def os_error_text(error: OSError) -> str:
    """The reason for `error`, for our sentence that names the file: translated for the
    common causes, else the system's own words behind a translated lead-in."""
    reasons = {
        errno.ENOENT: lambda: translate("OsError", "it does not exist"),
        errno.EACCES: lambda: translate("OsError", "permission denied"),
        errno.EPERM: lambda: translate("OsError", "permission denied"),
        errno.EROFS: lambda: translate("OsError", "the disk is read-only"),
        errno.ENOSPC: lambda: translate("OsError", "the disk is full"),
        errno.EDQUOT: lambda: translate("OsError", "the disk quota is used up"),
        errno.EISDIR: lambda: translate("OsError", "it is a folder"),
        errno.ENOTDIR: lambda: translate("OsError", "a part of the path is not a folder"),
        errno.EEXIST: lambda: translate("OsError", "it already exists"),
        errno.ENAMETOOLONG: lambda: translate("OsError", "the name is too long"),
        errno.EBUSY: lambda: translate("OsError", "it is in use"),
        errno.ETXTBSY: lambda: translate("OsError", "it is in use"),
        errno.EIO: lambda: translate("OsError", "the disk reported an input/output error"),
        errno.ELOOP: lambda: translate("OsError", "too many symbolic links"),
        errno.EMFILE: lambda: translate("OsError", "too many files are open"),
    }
    reason = reasons.get(error.errno or 0)
    if reason is not None:
        return reason()
    detail = error.strerror or str(error) or type(error).__name__
    return translate("OsError", "system error: {0}").format(detail)
