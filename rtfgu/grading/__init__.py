"""Assignments and the autograder: student stubs generated from the marked solutions, and a
grader that runs a submission's files in sandboxed child processes, one per test.

    python -m rtfgu.grading generate            write assignments/
    python -m rtfgu.grading grade a03 PATH      grade one submission
    python -m rtfgu.grading --help              everything else
"""
from .assignments import ASSIGNMENTS, get_assignment

__all__ = ["ASSIGNMENTS", "get_assignment"]
