"""What the tests of the Python module share: the repository root as the working directory (deck paths
are given as the command line's tests give them, relative to it) and the command line to compare with."""
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(autouse=True)
def in_repository(monkeypatch):
    monkeypatch.chdir(ROOT)


def sphdeck_binary() -> str:
    """The command line built beside the module (ctest passes it), else build/sphdeck."""
    return os.environ.get("SPHDECK_BINARY") or str(ROOT / "build" / "sphdeck")


def run_cli(*args, input_text=None) -> subprocess.CompletedProcess:
    return subprocess.run([sphdeck_binary(), *args], input=input_text, capture_output=True, text=True, cwd=ROOT)
