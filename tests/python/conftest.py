# SPDX-License-Identifier: Apache-2.0
"""pytest fixtures of the Python package's tests; the helpers are in support.py."""
import pytest

from support import RECORDINGS, recording


@pytest.fixture(params=sorted(RECORDINGS), ids=lambda n: RECORDINGS[n])
def real_recording(request):
    """Each real recording in turn: (path, the format its reader reports)."""
    return recording(request.param), RECORDINGS[request.param]
