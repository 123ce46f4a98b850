"""Shared fixtures: the repository root and the `stickiness` CLI binary for identity tests."""

import os
import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def root() -> pathlib.Path:
    return ROOT


@pytest.fixture(scope="session")
def cli() -> str:
    """The `stickiness` binary: $STICKINESS_CLI (set by `cargo xtask test`), else the workspace's
    dev build, else one on PATH. The identity tests need it; they fail, never skip, without it."""
    candidates = [os.environ.get("STICKINESS_CLI"), str(ROOT / "target" / "debug" / "stickiness")]
    for c in candidates:
        if c and pathlib.Path(c).is_file():
            return c
    found = shutil.which("stickiness")
    if found:
        return found
    raise RuntimeError(
        "no stickiness binary: run `cargo build -p cli` or set STICKINESS_CLI (cargo xtask test does)"
    )
