"""The wheel needs no Rust: installed into a fresh virtual environment whose PATH holds no
cargo or rustc, it answers V_stick (Section 4.4: 4.14 cm/s for CO2 grains of 60 um at
T_vis = 1e-9 s). `cargo xtask test` builds the wheel and sets STICKINESS_WHEEL."""

import os
import pathlib
import shutil
import subprocess
import sys

import pytest


def test_the_wheel_installs_and_runs_without_rust(tmp_path):
    wheel = os.environ.get("STICKINESS_WHEEL")
    if not wheel:
        pytest.fail("STICKINESS_WHEEL is not set: run the tests through `cargo xtask test`")
    name = pathlib.Path(wheel).name
    assert "abi3" in name and ("manylinux" in name or not sys.platform.startswith("linux")), name
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    # PATH without any directory that holds cargo or rustc
    dirs = [d for d in os.environ.get("PATH", "").split(os.pathsep) if d]
    no_rust = [d for d in dirs if not any(shutil.which(t, path=d) for t in ("cargo", "rustc"))]
    path = os.pathsep.join([str(venv / "bin")] + no_rust)
    assert shutil.which("cargo", path=path) is None and shutil.which("rustc", path=path) is None
    env = dict(os.environ, PATH=path)
    env.pop("CARGO", None)
    python = str(venv / "bin" / "python")
    pip = [python, "-m", "pip", "install", "--disable-pip-version-check", "-q", wheel]
    subprocess.run(pip, check=True, env=env)
    code = "import stickiness as st; print(st.v_stick('co2', 60e-6, 1e-9).v_stick)"
    out = subprocess.run([python, "-c", code], check=True, env=env, capture_output=True, text=True)
    assert 0.0413 < float(out.stdout) <= 0.0414
