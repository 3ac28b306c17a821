"""geocomp.study runs `geocomp study` in-process: a material-point study sweeping Young's
modulus (a second in all), its summary equal to the command line's study.json, the closed
forms of an elastic-perfectly plastic Mohr-Coulomb point under constant lateral stress, reuse,
and bad studies raising the command line's CaseError."""
import json
import math
import os
import pathlib
import tempfile
import unittest

import numpy

import geocomp
from support import run_cli

MODULI = ("200e6", "400e6", "800e6")  # yield at 2.2, 1.1 and 0.54 % axial strain, all before the 10 % end
LATERAL = 2e6                   # lateral stress held by the program [Pa, compression]
COHESION, FRICTION_DEG = 1e5, 30.0  # the continuum section's defaults (constant: no hardening)


def write_point_case(folder):
    """A material-point case: axial compression to eps_z = -10 % under 2 MPa lateral stress
    (the default isotropic start), the default Mohr-Coulomb continuum."""
    path = folder / "point.prm"
    path.write_text("set engines = material-point\n"
                    "subsection program\n  set sampling interval = 0.0005\n  subsection stage 1\n"
                    f"    set x = stress -{LATERAL:g}\n    set y = stress -{LATERAL:g}\n    set z = rate -1\n"
                    "    set stop when = eps_zz <= -0.1\n    set max duration = 1\n  end\nend\n"
                    f"subsection output\n  set directory = {folder / 'unused'}\n  set fields = false\nend\n")
    return path


def write_study(folder, entry="continuum/youngs modulus", values=", ".join(MODULI)):
    write_point_case(folder)
    path = folder / "study.prm"
    path.write_text("set title = stiffness series\nsubsection study\n  set base case = point.prm\n"
                    f"  set swept entry = {entry}\n  set values = {values}\n"
                    f"  set output directory = {folder / 'out'}\nend\n")
    return path


def same(value, reported):
    """A summary number (NaN where missing) against study.json's (null where missing)."""
    return reported is None and math.isnan(value) or value == reported


class AStudyFromPython(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory(prefix="geocomp-python-study-")
        root = pathlib.Path(cls.folder.name)
        cls.file = write_study(root)
        done = run_cli("study", str(cls.file), "--force")
        if done.returncode != 0:
            raise AssertionError(f"geocomp study failed ({done.returncode}): {done.stderr}")
        cls.reported = json.loads((root / "out/report/study.json").read_text())
        cls.seen = []
        cls.result = geocomp.study(str(cls.file), force=True, progress=cls.seen.append)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_reads_the_study_with_the_command_lines_reader(self):
        s = geocomp.read_study(str(self.file))
        self.assertEqual(s.swept_entry, "continuum/youngs modulus")
        self.assertEqual(s.against, "continuum/youngs modulus")
        self.assertEqual([c.name for c in s.cases], ["point_" + e for e in MODULI])
        self.assertTrue(numpy.array_equal(s.x, numpy.array(MODULI, dtype=float)))
        for c in s.cases:
            self.assertEqual(pathlib.Path(c.folder), pathlib.Path(s.output) / "cases" / c.name)
            self.assertEqual(float(c.case.get("continuum/youngs modulus")), c.x)
            self.assertIn("continuum/youngs modulus = ", c.label)

    def test_its_summary_equals_the_study_json_the_command_line_writes(self):
        self.assertTrue(self.result.complete)
        self.assertEqual([c["name"] for c in self.reported["cases"]], list(self.result.summary["case"]))
        for k, case in enumerate(self.reported["cases"]):
            self.assertEqual(case["status"], "complete")
            (engine,) = case["engines"]
            self.assertEqual(self.result.summary["x"][k], case["x"])
            for key in geocomp.SUMMARY_KEYS:
                with self.subTest(case=case["name"], quantity=key):
                    self.assertIn(key, engine)
                    self.assertTrue(same(self.result.summary[key][k], engine[key]),
                                    f"{self.result.summary[key][k]!r} != {engine[key]!r}")
        written = json.loads(pathlib.Path(self.result.json).read_text())
        self.assertEqual(written["cases"], self.reported["cases"])  # the same file, rewritten by Python
        self.assertTrue(pathlib.Path(self.result.report).is_file())

    def test_peak_stress_is_mohr_coulombs_for_every_stiffness_and_the_secant_modulus_is_E(self):
        # Constant lateral stress s3, yield at s1 = N s3 + 2 c sqrt(N), N = (1 + sin phi) / (1 - sin phi),
        # whatever E; below it the axial response under constant lateral stress is E itself.
        n = (1 + math.sin(math.radians(FRICTION_DEG))) / (1 - math.sin(math.radians(FRICTION_DEG)))
        expected_peak = n * LATERAL + 2 * COHESION * math.sqrt(n)
        table = self.result.summary_of("material-point")
        self.assertTrue(numpy.array_equal(table["x"], numpy.array(MODULI, dtype=float)))
        numpy.testing.assert_allclose(table["peak_stress_Pa"], expected_peak, rtol=1e-3)  # 6e-4 measured
        # The curve's strain is logarithmic and sampled every 0.05 %: the secant departs from E by
        # 0.8, 0.4, 0.2 % (measured), halving with E as the strain at half the peak does.
        numpy.testing.assert_allclose(table["secant_modulus_Pa"] / table["x"], 1.0, rtol=0.015)
        self.assertTrue(numpy.all(numpy.diff(table["secant_modulus_Pa"]) > 0))

    def test_returns_each_cases_response_and_reports_its_progress(self):
        for c in self.result.cases:
            r = c.responses["material-point"]
            self.assertEqual(r.status, "complete")
            self.assertAlmostEqual(float(r.log_strain[-1, 2, 2]), math.log(0.9), delta=0.005)
            self.assertEqual(c.summaries["material-point"]["metrics"]["peak_stress"],
                             c.summaries["material-point"]["peak_stress_Pa"])
        self.assertEqual({p["case"] for p in self.seen}, {c.name for c in self.result.cases})
        self.assertEqual({p["engine"] for p in self.seen}, {"material-point"})

    def test_reuses_up_to_date_results_without_running_again(self):
        seen = []
        again = geocomp.study(geocomp.read_study(str(self.file)), progress=seen.append)
        self.assertEqual(seen, [])
        for key, values in self.result.summary.items():
            self.assertTrue(numpy.array_equal(values, again.summary[key]), key)

    def test_stops_when_the_progress_callback_raises_and_raises_it_again(self):
        class Enough(Exception):
            pass

        def stop(p):
            if p["time"] > 0:
                raise Enough()
        folder = pathlib.Path(self.folder.name) / "stopped"
        folder.mkdir()
        with self.assertRaises(Enough):
            geocomp.study(str(write_study(folder)), force=True, progress=stop)
        reported = json.loads((folder / "out/report/study.json").read_text())
        self.assertTrue(all(c["status"].startswith("failed") for c in reported["cases"]))


class ABadStudy(unittest.TestCase):
    def check_refused(self, parameter, **entries):
        with tempfile.TemporaryDirectory(prefix="geocomp-python-bad-study-") as folder:
            path = write_study(pathlib.Path(folder), **entries)
            cli = run_cli("study", str(path))
            self.assertEqual(cli.returncode, 2, cli.stderr)
            with self.assertRaises(geocomp.CaseError) as raised:
                geocomp.study(str(path))
            self.assertEqual("error: " + str(raised.exception) + "\n", cli.stderr)
            self.assertEqual(raised.exception.file, str(path))
            self.assertEqual(raised.exception.parameter, parameter)
            self.assertFalse((pathlib.Path(folder) / "out").exists())  # nothing written
            return str(raised.exception)

    def test_a_swept_entry_no_case_has_raises_case_error_naming_it(self):
        message = self.check_refused("study/swept entry", entry="continuum/no such entry")
        self.assertIn("no such entry", message)

    def test_a_value_its_pattern_refuses_raises_case_error_naming_the_values(self):
        message = self.check_refused("study/values", values="200e6, -5")
        self.assertIn("youngs modulus", message)


if __name__ == "__main__":
    unittest.main(verbosity=2)
