"""The calibrated pair (calibration/pair continuum = calibrated): curves made by the material
point with known parameters, given as the targets, are recovered by `geocomp pair` to 1e-6;
the material point then runs the calibrated section and reproduces the target's curve; its
results store that section; a second pair reuses them; the report judges it "within scatter"
of the target for every metric, and a continuum with a lower peak friction "outside"; its
model ladder (constant against tables) is in the fit report and the pair's report alike;
inconsistent cases are refused."""
import os
import pathlib
import tempfile
import unittest

import numpy

import geocomp
from support import largest, run_cli

TRUTH = {"E": 80e6, "nu": 0.3, "cohesion[0]": 30e3, "friction[1]": 32.0, "dilatancy[1]": 8.0}
CONTINUUM = """subsection continuum
  set model = {model}
  set youngs modulus = {E}
  set poisson ratio = {nu}
  set cohesion = 0:{c}
  set friction angle = 0:20, 0.02:{phi}, 0.08:27
  set dilatancy angle = 0:0, 0.02:{psi}
end
"""
PROGRAM = """set engines = material-point
subsection specimen
  set isotropic pressure = {p}
end
subsection program
  set sampling interval = 0.0015
  subsection stage 1
    set x = stress -{p}
    set y = stress -{p}
    set z = rate -1
    set stop when = eps_zz <= -0.06
    set max duration = 1
  end
end
subsection output
  set directory = {out}
  set fields = false
end
"""


def write_case(path, p, out, extra="", model="mohr-coulomb", E=80e6, nu=0.3, c=30e3, phi=32, psi=8):
    path.write_text(PROGRAM.format(p=p, out=out) + CONTINUUM.format(model=model, E=E, nu=nu, c=c, phi=phi, psi=psi)
                    + extra)
    return str(path)


class ACalibratedPair(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory(prefix="geocomp-calibrated-pair-")
        cls.root = pathlib.Path(cls.folder.name)
        cls.targets = []
        for p in (1e5, 2e5, 4e5):  # the "DEM": the material point with the truth, three confinements
            out = cls.root / f"truth-{p:g}"
            done = run_cli("material-point", write_case(cls.root / f"truth-{p:g}.prm", p, out))
            assert done.returncode == 0, done.stderr
            cls.targets.append(str(out / "material-point.h5"))
        cls.calibration = ("subsection calibration\n  set targets = " + ", ".join(cls.targets) + "\n"
                           f"  set scatter = {cls.targets[1]}\n"
                           "  set free parameters = E, nu, cohesion, friction[1], dilatancy[1]\n"
                           "  set starting values = case\n  set pair continuum = calibrated\n"
                           "  set ladder = mohr-coulomb constant, mohr-coulomb tables\nend\n")
        cls.out = cls.root / "fit"
        cls.case = write_case(cls.root / "fit.prm", 2e5, cls.out, cls.calibration, E=104e6, nu=0.22, c=10e3, phi=28,
                              psi=3)
        cls.first = run_cli("pair", cls.case)
        cls.second = run_cli("pair", cls.case)
        cls.other_out = cls.root / "other"  # a different continuum, as given: phi_peak 28 degrees
        other = write_case(cls.root / "other.prm", 2e5, cls.other_out,
                           f"subsection calibration\n  set scatter = {cls.targets[1]}\nend\n", phi=28)
        cls.other = run_cli("pair", other)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_recovers_the_known_parameters_to_1e_6(self):
        self.assertEqual(self.first.returncode, 0, self.first.stderr)
        rows = {}
        for line in (self.out / "calibration" / "parameters.tsv").read_text().splitlines():
            if line and not line.startswith("#"):
                name, start, value, error = line.split("\t")
                rows[name] = float(value)
        for name, truth in TRUTH.items():
            with self.subTest(parameter=name):
                self.assertAlmostEqual(rows[name] / truth, 1.0, delta=1e-6)

    def test_the_material_point_runs_the_calibrated_section_and_reproduces_the_target(self):
        mine = geocomp.read_results(str(self.out / "material-point.h5"))
        target = geocomp.read_results(self.targets[1])  # the same program at 0.2 MPa
        self.assertEqual(len(mine), len(target))
        difference = float(numpy.max(numpy.abs(mine.stress - target.stress)))
        self.assertLessEqual(difference, 1e-6 * largest(target.stress))
        self.assertIn("set pair continuum = calibrated", mine.meta["case_text"])
        self.assertIn("set youngs modulus  = 80000000", mine.meta["case_text"])  # the section appended
        index = (self.out / "report" / "index.html").read_text()
        self.assertIn("the continuum section calibrated to 3 results file(s) of calibration/targets", index)

    def test_the_report_lists_the_curves_calibrated_on_with_their_fit_residuals(self):
        import json
        curves = json.loads((self.out / "report" / "metrics.json").read_text())["calibration_curves"]
        self.assertEqual([c["curve"] for c in curves], self.targets)
        for c in curves:
            self.assertEqual(c["role"], "calibrated on")
            for q in ("rms_q", "rms_p", "rms_eps_v"):
                self.assertLess(c[q], 1e-6, f"{c['curve']} {q}")

    def test_the_report_says_within_scatter_for_every_metric_and_outside_for_another_continuum(self):
        import json
        within = json.loads((self.out / "report" / "metrics.json").read_text())["scatter"]
        self.assertEqual(within["specimens"], [self.targets[1]])
        defined = [r for r in within["rows"] if r["verdicts"]["material point"] != "n/a"]
        self.assertGreaterEqual(len(defined), 6)
        for r in defined:
            self.assertEqual(r["verdicts"]["material point"], "within scatter", r["key"])
        self.assertEqual(self.other.returncode, 0, self.other.stderr)
        outside = json.loads((self.other_out / "report" / "metrics.json").read_text())["scatter"]
        verdicts = {r["key"]: r["verdicts"]["material point"] for r in outside["rows"]}
        self.assertEqual(verdicts["peak_stress_MPa"], "outside")
        self.assertIn("Specimen scatter", (self.other_out / "report" / "index.html").read_text())

    def test_the_report_carries_the_model_ladder_of_the_fit(self):
        import json
        fit = json.loads((self.out / "calibration" / "fit.json").read_text())["ladder"]
        report = json.loads((self.out / "report" / "metrics.json").read_text())["ladder"]
        self.assertEqual([r["model"] for r in report], ["mohr-coulomb constant", "mohr-coulomb tables"])
        self.assertEqual(report, fit)
        constant, tables = report
        self.assertEqual((constant["k"], tables["k"]), (5, 5))  # E, nu, c, phi, psi: one value or one knot each
        self.assertLess(tables["rss"], 1e-12)  # the truth is a tables model
        self.assertGreater(constant["rss"], 1e-4)  # its hardening and softening are not constant
        self.assertIn("Model ladder", (self.out / "report" / "index.html").read_text())

    def test_a_second_pair_refits_to_the_same_bits_and_reuses_the_results(self):
        self.assertEqual(self.second.returncode, 0, self.second.stderr)
        self.assertIn("material-point: up-to-date results reused", self.second.stdout)

    def test_refuses_a_calibrated_pair_without_dem_or_targets_and_a_nikolaevsky_continuum(self):
        bare = write_case(self.root / "bare.prm", 2e5, self.root / "bare",
                          "subsection calibration\n  set pair continuum = calibrated\nend\n")
        done = run_cli("pair", bare)
        self.assertEqual(done.returncode, 2)
        self.assertIn("parameter 'calibration/pair continuum'", done.stderr)
        self.assertIn("expected 'dem' among the engines or at least one target", done.stderr)
        self.assertFalse(os.path.exists(self.root / "bare"))
        case = geocomp.read_case(self.case)
        with self.assertRaises(geocomp.CaseError) as raised:
            case.set("continuum/model", "nikolaevsky")
            geocomp.pair(case, output=str(self.root / "nikolaevsky"))
        self.assertIn("got nikolaevsky", str(raised.exception))


if __name__ == "__main__":
    unittest.main(verbosity=2)
