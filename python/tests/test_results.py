"""Responses as numpy arrays, the h5py reader, metrics and the Rudnicki-Rice functions."""
import json
import math
import os
import unittest

import numpy

import geocomp
from support import ARRAYS, DEMO, SOURCE_DIR, cli_results, run_cli


class AResultsFile(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder, cls.path = cli_results("material-point")
        cls.case = geocomp.read_case(DEMO)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_the_h5py_reader_and_the_in_memory_response_agree(self):
        from_h5py = geocomp.read_results(self.path)
        in_memory = geocomp.Response.read(self.path)
        self.assertEqual(len(in_memory), len(from_h5py))
        for name in ARRAYS:
            with self.subTest(array=name):
                numpy.testing.assert_array_equal(getattr(in_memory, name), getattr(from_h5py, name))
        for name, column in from_h5py.extras.items():
            numpy.testing.assert_array_equal(in_memory.extras[name], column)
        self.assertEqual(in_memory.branches, from_h5py.branches)
        self.assertEqual(in_memory.stage_names, from_h5py.stage_names)
        self.assertEqual(from_h5py.meta["case_text"], self.case.text)
        self.assertEqual(from_h5py.meta["parameters"], self.case.parameters())
        self.assertEqual(from_h5py.status, "complete")

    def test_response_arrays_are_read_only_views_of_one_buffer(self):
        r = geocomp.Response.read(self.path)
        first, second = r.stress, r.stress
        self.assertTrue(numpy.shares_memory(first, second))
        self.assertFalse(first.flags.writeable)
        self.assertEqual(first.shape, (len(r), 3, 3))
        del r
        self.assertTrue(numpy.isfinite(first).all())  # the view keeps the columns alive
        with self.assertRaises(ValueError):
            first[0, 0, 0] = 1.0

    def test_tensors_are_laid_out_row_by_row_and_tension_positive(self):
        r = geocomp.Response.read(self.path)
        # The demo consolidates to 2 MPa: compression, negative mean stress at the start.
        self.assertAlmostEqual(r.mean_stress[0], -2e6, delta=1.0)
        numpy.testing.assert_allclose(r.mean_stress, numpy.trace(r.stress, axis1=1, axis2=2) / 3, rtol=1e-15)
        self.assertTrue((r.tau_max >= 0).all())

    def test_metrics_are_the_ones_geocomp_compare_prints(self):
        done = run_cli("compare", DEMO, "--output", self.folder.name)
        self.assertEqual(done.returncode, 0, done.stderr)
        printed = json.loads(done.stdout)
        table = next(iter(printed["metrics"].values()))
        mine = geocomp.metrics(geocomp.Response.read(self.path), self.case)
        self.assertEqual(mine["kind"], table["curve"])
        self.assertEqual(mine["elastic_limit_method"], table["elastic_limit_method"])
        self.assertAlmostEqual(mine["peak_stress"] / 1e6, table["peak_stress_MPa"], delta=1e-4 * table["peak_stress_MPa"])
        self.assertAlmostEqual(100 * mine["peak_strain"], table["peak_strain_pct"], delta=1e-4 * table["peak_strain_pct"])
        predicted = printed["rudnicki_rice"]["predicted"]
        onset = geocomp.rudnicki_rice_onset(geocomp.Response.read(self.path), self.case)
        self.assertEqual(onset["found"], predicted["found"])
        if onset["found"]:
            self.assertAlmostEqual(100 * onset["strain"], predicted["onset_strain_pct"],
                                   delta=1e-4 * abs(predicted["onset_strain_pct"]))


class TheRudnickiRiceClosedForm(unittest.TestCase):
    def test_gives_the_critical_hardening_and_band_angle_of_the_paper(self):
        mu, beta, nu, N = 0.6, 0.3, 0.25, -1 / math.sqrt(3)
        p = geocomp.rudnicki_rice(mu, beta, nu, N)
        h = (1 + nu) / (9 * (1 - nu)) * (beta - mu) ** 2 - (1 + nu) / 2 * (N + (beta + mu) / 3) ** 2
        alpha = (2 / 3 * (1 + nu) * (beta + mu) - N * (1 - 2 * nu)) / math.sqrt(4 - 3 * N ** 2)
        self.assertAlmostEqual(p["critical_hardening_over_G"], h, places=12)
        self.assertAlmostEqual(p["alpha"], alpha, places=12)
        self.assertAlmostEqual(p["band_normal_angle"], math.pi / 4 + 0.5 * math.asin(alpha), places=12)
        self.assertTrue(p["closed_form_valid"])

    def test_reads_the_deviatoric_state_of_a_stress(self):
        compression = numpy.diag([-1e6, -1e6, -3e6])  # axisymmetric compression along z
        self.assertAlmostEqual(geocomp.deviatoric_state(compression), 1 / math.sqrt(3), places=12)
        self.assertEqual(geocomp.rudnicki_rice_from_drucker_prager(0.2, 0.3, 0.25),
                         {"mu": 0.6000000000000001, "beta": 0.3, "nu": 0.25})


class ARunWithProgress(unittest.TestCase):
    def setUp(self):
        os.chdir(SOURCE_DIR)

    def test_reports_every_sample_of_each_path_in_time_order(self):
        seen = []
        r = geocomp.run(geocomp.read_case(DEMO), "material-point", progress=seen.append)
        self.assertGreaterEqual(len(seen), len(r) - 1)
        self.assertEqual({p["branch"] for p in seen}, set(r.branch.tolist()))
        for branch in set(r.branch.tolist()):
            times = [p["time"] for p in seen if p["branch"] == branch]
            self.assertEqual(times, sorted(times))
        self.assertTrue(all(0 <= p["stage_fraction"] <= 1 for p in seen))

    def test_stops_with_the_exception_the_callback_raised(self):
        class Enough(Exception):
            pass

        def stop(p):
            if p["time"] > 0.05:
                raise Enough()

        with self.assertRaises(Enough):
            geocomp.run(geocomp.read_case(DEMO), "material-point", progress=stop)

    def test_that_fails_mid_way_raises_run_error_with_the_samples_so_far(self):
        # A stress axis driven into tension past the Mohr-Coulomb apex (tests/cli/ContinuumFailureTest.cpp).
        apex = geocomp.Case.parse(
            "set engines = material-point\n"
            "subsection specimen\n  set isotropic pressure = 1e5\nend\n"
            "subsection continuum\n  set cohesion = 0:10e3\n  set friction angle = 0:30\n"
            "  set dilatancy angle = 0:0\nend\n"
            "subsection program\n  set sampling interval = 0.1\n  subsection stage 1\n"
            "    set x = stress -1e5\n    set y = stress -1e5\n    set z = stress 1e6\n"
            "    set stop when = stage_time >= 2\n    set max duration = 4\n  end\nend\n", "apex.prm")
        with self.assertRaises(geocomp.RunError) as raised:
            geocomp.run(apex, "material-point", progress=lambda p: None)
        self.assertIn("did not converge", str(raised.exception))
        partial = raised.exception.response
        self.assertTrue(partial.status.startswith("failed"), partial.status)
        self.assertGreater(len(partial), 0)
        self.assertLess(partial.time[-1], 2.0)

    def test_refuses_an_engine_the_case_cannot_run(self):
        with self.assertRaises(geocomp.CaseError) as raised:
            geocomp.run(geocomp.read_case(DEMO), "no-such-engine")
        self.assertIn("no-such-engine", str(raised.exception))


if __name__ == "__main__":
    unittest.main(verbosity=2)
