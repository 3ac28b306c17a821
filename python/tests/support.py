"""What the Python tests share: the built command line, run as a user runs it."""
import os
import pathlib
import subprocess

SOURCE_DIR = pathlib.Path(os.environ.get("GEOCOMP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DEMO = "cases/demo.prm"


def geocomp_exe():
    """The `geocomp` executable ctest names (GEOCOMP_EXE), else build/compare/cli/geocomp."""
    return os.environ.get("GEOCOMP_EXE", str(SOURCE_DIR / "build/compare/cli/geocomp"))


def run_cli(*args, cwd=SOURCE_DIR):
    """Runs `geocomp ARGS` in `cwd`; returns the CompletedProcess (text stdout, stderr)."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return subprocess.run([geocomp_exe(), *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


def largest(a):
    """The largest magnitude in an array (1 for an all-zero one), the scale of a relative difference."""
    import numpy
    m = float(numpy.max(numpy.abs(a))) if numpy.size(a) else 0.0
    return m if m > 0 else 1.0
