"""Paths the Python tests share: the source tree, the program built beside the module."""

import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("HYDRODDA_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("HYDRODDA_BINARY", str(SOURCE_DIR / "build/bin/hydrodda"))
VERIFICATION = SOURCE_DIR / "scenarios/verification"
BAD_SCENARIOS = SOURCE_DIR / "tests/cli/bad_scenarios"


def run_program(*arguments, cwd=None):
    """The hydrodda program's exit code, stdout and stderr."""
    done = subprocess.run([BINARY, *map(str, arguments)], cwd=cwd, capture_output=True, text=True, timeout=300)
    return done.returncode, done.stdout, done.stderr


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Runs the test in its own empty folder."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
