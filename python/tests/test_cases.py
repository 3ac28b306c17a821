"""Cases from Python: the command line's readers, messages and validation."""
import glob
import math
import os
import unittest

import geocomp
from support import DEMO, SOURCE_DIR, run_cli


class ACaseFile(unittest.TestCase):
    def setUp(self):
        os.chdir(SOURCE_DIR)

    def test_every_bad_case_raises_the_message_geocomp_check_prints(self):
        files = sorted(glob.glob("tests/bad_cases/*.prm") + glob.glob("tests/bad_cases/*.json"))
        self.assertGreater(len(files), 40)
        for path in files:
            with self.subTest(case=path):
                cli = run_cli("check", path)
                self.assertEqual(cli.returncode, 2, cli.stderr)
                with self.assertRaises(geocomp.CaseError) as raised:
                    geocomp.check(path)
                self.assertEqual("error: " + str(raised.exception) + "\n", cli.stderr)
                self.assertEqual(raised.exception.file, path)

    def test_an_engine_refusal_is_raised_by_validate_not_by_reading(self):
        case = geocomp.read_case("tests/bad_cases/fem_dem_lognormal_grains.prm")
        with self.assertRaises(geocomp.CaseError) as raised:
            case.validate()
        self.assertEqual(raised.exception.parameter, "dem rve")
        self.assertIn("lognormal", str(raised.exception))

    def test_a_good_case_passes_check(self):
        self.assertEqual(run_cli("check", DEMO).returncode, 0)
        case = geocomp.check(DEMO)
        self.assertEqual(case.engines, ["dem", "continuum", "material-point"])
        case.validate()

    def test_get_returns_what_set_wrote(self):
        case = geocomp.read_case(DEMO)
        self.assertEqual(case.get("continuum/youngs modulus"), "9e+07")
        case.set("continuum/youngs modulus", 120e6)
        self.assertEqual(case.get("continuum/youngs modulus"), "1.2e+08")
        case["continuum/cohesion"] = "0:30e3, 0.05:5e3"
        self.assertEqual(case["continuum/cohesion"], "0:3e+04, 0.05:5e+03")
        case.set("program/stage 1/lambda", 0.5)
        self.assertEqual(case.get("program/stage 1/lambda"), "0.5")
        self.assertIn("continuum/youngs modulus = 1.2e+08", case.parameters())
        case["output/fields"] = False
        self.assertEqual(case["output/fields"], "false")

    def test_a_refused_value_raises_the_readers_message_and_leaves_the_case_unchanged(self):
        case = geocomp.read_case(DEMO)
        text = case.text
        with self.assertRaises(geocomp.CaseError) as raised:
            case.set("continuum/poisson ratio", "0.7")
        self.assertEqual(raised.exception.file, DEMO)
        self.assertIn("poisson ratio", str(raised.exception))
        self.assertEqual(case.text, text)
        self.assertEqual(case.get("continuum/poisson ratio"), "0.25")
        with self.assertRaises(geocomp.CaseError):
            case.set("continuum/no such entry", "1")
        with self.assertRaises(KeyError):
            case.get("continuum/no such entry")

    def test_set_works_on_a_json_case_too(self):
        text = ('{"engines": "material-point", "continuum": {"youngs modulus": 50e6}, '
                '"program": {"stage 1": {"mode": "isochoric", "isochoric rate": 0.2, '
                '"stop when": "gamma_max >= 0.01"}}}')
        case = geocomp.Case.parse(text, "mine.json")
        self.assertEqual(case.get("continuum/youngs modulus"), "5e+07")
        case.set("continuum/youngs modulus", 70e6)
        self.assertEqual(case.get("continuum/youngs modulus"), "7e+07")
        self.assertEqual(geocomp.Case.parse(case.text, "again.json").get("continuum/youngs modulus"), "7e+07")

    def test_a_changed_entry_changes_the_run(self):
        case = geocomp.read_case(DEMO)
        before = geocomp.run(case, "material-point")
        case.set("continuum/friction angle", "0:20, 0.04:35, 0.15:33")
        after = geocomp.run(case, "material-point")
        stronger = geocomp.material_point(geocomp.read_case(DEMO),
                                          {"continuum/friction angle": "0:20, 0.04:35, 0.15:33"})
        peak_before = geocomp.metrics(before, case)["peak_stress"]
        peak_after = geocomp.metrics(after, case)["peak_stress"]
        self.assertTrue(math.isfinite(peak_before))
        self.assertGreater(peak_after, 1.05 * peak_before)
        self.assertEqual(stronger.tau_max.tolist(), after.tau_max.tolist())


if __name__ == "__main__":
    unittest.main(verbosity=2)
