"""Shared by the WGSL tests: one device per test process, skipping only where no adapter
exists at all (with the package to install in the message)."""
from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def wgpu_device():
    from rtfgu.wgsl.device import NoAdapterError, get_device

    try:
        return get_device()[1]
    except NoAdapterError as error:
        pytest.skip(str(error))
