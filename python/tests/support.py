"""What the Python tests share: the built command line, run as a user runs it."""
import os
import pathlib
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
