"""Helpers that run inside the sandboxed child, next to the student's code.

They turn what the student's functions return into plain JSON values, and say in words
when a value has the wrong type, so that the grader only ever compares numbers.
"""
from __future__ import annotations

import math
import os
import traceback


class StudentError(Exception):
    """The student's code returned something of the wrong kind; the message says what."""


class StoppedFunction(StudentError):
    """A student function that an earlier test's time limit stopped was called again."""


def stop_functions(stopped) -> None:
    """Replace each student function of ``stopped`` ([file under rtfgu/, function name, line,
    test number]: where an earlier test's time limit found the code) by one that raises
    StoppedFunction: the tests that would run it again fail at once, with the place, instead
    of each waiting out its own time limit (rtfgu.grading.timeouts)."""
    import importlib
    import types

    for relpath, name, line, number in stopped:
        module = importlib.import_module("rtfgu." + relpath[:-len(".py")].replace("/", "."))
        owners = [module] + [v for v in vars(module).values() if isinstance(v, type) and v.__module__ == module.__name__]
        found = [(owner, key, f) for owner in owners for key, f in vars(owner).items()
                 if isinstance(f, types.FunctionType) and f.__code__.co_name == name
                 and f.__code__.co_firstlineno <= line]
        if not found:
            continue
        owner, key, f = max(found, key=lambda item: item[2].__code__.co_firstlineno)
        label = ("%s.%s" % (owner.__name__, key)) if isinstance(owner, type) else key
        message = ("%s was not run: it did not finish in test %s (your code was at rtfgu/%s, line %d)"
                   % (label, number, relpath, line))

        def stopped_function(*args, _message=message, **kwargs):
            raise StoppedFunction(_message)

        setattr(owner, key, stopped_function)


def _type_name(value) -> str:
    return type(value).__name__


def num(value, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) and not hasattr(value, "__float__"):
        raise StudentError("%s should be a number, but it is %r (of type %s)" % (what, value, _type_name(value)))
    return float(value)


def vec(value, what: str) -> list:
    try:
        x, y, z = value.x, value.y, value.z
    except AttributeError:
        raise StudentError("%s should be a Float3, but it is %r (of type %s)"
                           % (what, value, _type_name(value))) from None
    return [num(x, what + ".x"), num(y, what + ".y"), num(z, what + ".z")]


def boolean(value, what: str) -> bool:
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    raise StudentError("%s should be True or False, but it is %r (of type %s)" % (what, value, _type_name(value)))


def describe_exception(error: BaseException) -> str:
    """The exception in words, with the place in the student's files where it happened."""
    if isinstance(error, StudentError):
        return str(error)
    if isinstance(error, MemoryError):
        return "MemoryError: your code ran out of memory (the limit is %s MB per test)" % (
            os.environ.get("RTFGU_MEMORY_MB", "?"))
    if isinstance(error, NotImplementedError) and str(error)[:1] == "a" and ":" in str(error):
        return "NotImplementedError(%r): this part is not written yet" % str(error)
    if isinstance(error, SyntaxError):
        return "SyntaxError in %s, line %s: %s" % (_short(error.filename or "?"), error.lineno, error.msg)
    where = ""
    for frame in reversed(traceback.extract_tb(error.__traceback__)):
        short = _short(frame.filename)
        if short is not None and "grading" not in frame.filename and "probes" not in frame.filename:
            where = " (in %s, line %d, in %s: %s)" % (short, frame.lineno, frame.name, (frame.line or "").strip())
            break
    return "%s: %s%s" % (type(error).__name__, error, where)


def _short(filename: str):
    marker = os.sep + "rtfgu" + os.sep
    if marker in filename:
        return filename.split(marker, 1)[1]
    return None


class Cases:
    """Run one case after another; a case that raises costs that case only."""

    def __init__(self):
        self.cases = []

    def run(self, label: str, fn, **inputs) -> None:
        entry = {"label": label, "in": inputs}
        try:
            entry["out"] = fn()
        except StudentError as error:
            entry["error"] = str(error)
        except MemoryError:
            raise  # out of memory: the whole test stops (the next case would only run out again)
        except Exception as error:
            entry["error"] = describe_exception(error)
        self.cases.append(entry)

    def result(self) -> dict:
        return {"cases": self.cases}


def image(array) -> dict:
    import numpy as np

    array = np.asarray(array, dtype=np.float64)
    return {"image": array.tolist(), "shape": list(array.shape)}


def finite(x: float) -> bool:
    return math.isfinite(x)
