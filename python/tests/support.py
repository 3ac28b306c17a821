"""What the Python tests share: the built command line, run as a user runs it."""
import os
import pathlib
import re
import subprocess

SOURCE_DIR = pathlib.Path(os.environ.get("GEOCOMP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DEMO = "cases/demo.prm"
# Every per-sample array of a response, as geocomp.run and geocomp.read_results name them.
ARRAYS = ("time", "strain", "log_strain", "stress", "stress_mean", "volumetric_strain",
          "gamma_max", "tau_max", "mean_stress", "stage", "branch")


def geocomp_exe():
    """The `geocomp` executable ctest names (GEOCOMP_EXE), else build/compare/cli/geocomp."""
    return os.environ.get("GEOCOMP_EXE", str(SOURCE_DIR / "build/compare/cli/geocomp"))


def run_cli(*args, cwd=SOURCE_DIR):
    """Runs `geocomp ARGS` in `cwd`; returns the CompletedProcess (text stdout, stderr)."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return subprocess.run([geocomp_exe(), *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


def small_demo(folder):
    """The demo's case made small for a test (343 spheres, a 2^3 cube, to gamma 10 % with its
    fixed branches, no bisection), written into `folder`; returns its path."""
    text = (SOURCE_DIR / DEMO).read_text()
    for entry, value in (("particles", "343"), ("cells per edge", "2"), ("stop when", "gamma_max >= 0.1"),
                         ("locate elastic limit", "false"), ("directory", folder)):
        text = re.sub(r"set " + entry + r" *= [^\n]*", "set " + entry + " = " + value, text)
    path = os.path.join(folder, "small_demo.prm")
    with open(path, "w") as f:
        f.write(text)
    return path


def largest(a):
    """The largest magnitude in an array (1 for an all-zero one), the scale of a relative difference."""
    import numpy
    m = float(numpy.max(numpy.abs(a))) if numpy.size(a) else 0.0
    return m if m > 0 else 1.0


def cli_results(engine, case=DEMO):
    """Runs `geocomp ENGINE CASE` into a fresh temporary folder (from the source tree);
    returns the TemporaryDirectory (the caller cleans it up) and the results file's path."""
    import tempfile
    os.chdir(SOURCE_DIR)
    folder = tempfile.TemporaryDirectory(prefix="geocomp-python-")
    done = run_cli(engine, case, "--output", folder.name, "--force")
    if done.returncode != 0:
        folder.cleanup()
        raise AssertionError(f"geocomp {engine} failed ({done.returncode}): {done.stderr}")
    return folder, os.path.join(folder.name, engine + ".h5")
