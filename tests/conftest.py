"""Shared test configuration.

``--update-reference-images`` is the only way the committed images in
``tests/reference_images/`` are rewritten: without it an image test compares and fails,
it never regenerates silently.
"""
from __future__ import annotations

from pathlib import Path

import pytest

TESTS_DIR = Path(__file__).resolve().parent
REFERENCE_IMAGES_DIR = TESTS_DIR / "reference_images"
# Where a failing image test writes what it rendered and a diff (git-ignored).
OUTPUT_DIR = TESTS_DIR / "output"


def pytest_addoption(parser):
    parser.addoption(
        "--update-reference-images",
        action="store_true",
        default=False,
        help="rewrite tests/reference_images/*.png from the current renderer instead of comparing",
    )


@pytest.fixture
def update_reference_images(request) -> bool:
    return request.config.getoption("--update-reference-images")


@pytest.fixture
def reference_images_dir() -> Path:
    return REFERENCE_IMAGES_DIR


@pytest.fixture
def output_dir() -> Path:
    """Where a failing image test writes its images; created only when something is written."""
    return OUTPUT_DIR
