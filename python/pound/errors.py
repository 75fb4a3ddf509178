"""The exceptions pound raises: bad input, a failed analysis, outputs that cannot be written."""


class InputError(ValueError):
    """The model, record, set or an argument is wrong; nothing ran and nothing was written.

    ``file`` names the input (a path, or ``<dict>`` for a model given as a dict), ``path`` where
    in it (a JSON pointer such as ``/links/0/gap``, ``line 12``, ``accelerations[3]``, or empty)
    and ``message`` what was expected.
    """

    def __init__(self, file, path, message):
        self.file = file
        self.path = path
        self.message = message
        where = ": ".join(part for part in (file, path) if part)
        super().__init__(f"{where}: {message}" if where else message)

    def __reduce__(self):
        # Rebuilt from its parts, so that it crosses to another process (a process pool's worker).
        return (type(self), (self.file, self.path, self.message))


class AnalysisError(RuntimeError):
    """The analysis could not go on (Newton failed at the smallest step, the state diverged).

    ``time`` is when it stopped (None for a static pushover), ``reason`` why, and ``result`` the
    :class:`pound.Result` (or :class:`pound.Pushover`) up to then (None where no run was under
    way, e.g. a modal analysis).
    """

    def __init__(self, time, reason, result=None):
        self.time = time
        self.reason = reason
        self.result = result
        super().__init__(f"analysis failed at t = {time:.6g}: {reason}" if time is not None
                         else f"analysis failed: {reason}")

    def __reduce__(self):
        return (type(self), (self.time, self.reason, self.result))


class OutputError(OSError):
    """Results could not be written (a folder that cannot be made, a full disk)."""
