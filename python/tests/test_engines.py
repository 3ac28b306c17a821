"""The FE cube (MPI started in-process) and the DEM run from Python return the command line's curves
(on the demo made small: the agreement is the point, not the specimen)."""
import os
import tempfile
import unittest

import numpy

import geocomp
from support import SOURCE_DIR, largest, run_cli, small_demo

ARRAYS = ("time", "strain", "log_strain", "stress", "stress_mean", "stage", "branch")


class AnEngineRunInProcess(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.chdir(SOURCE_DIR)
        cls.folder = tempfile.TemporaryDirectory(prefix="geocomp-python-")
        cls.path = small_demo(cls.folder.name)
        cls.case = geocomp.read_case(cls.path)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def agrees_with_the_command_line(self, engine):
        done = run_cli(engine, self.path, "--output", self.folder.name, "--force")
        self.assertEqual(done.returncode, 0, done.stderr)
        written = geocomp.read_results(os.path.join(self.folder.name, engine + ".h5"))
        seen = []
        mine = geocomp.run(self.case, engine, output=self.folder.name, progress=seen.append)
        self.assertEqual(len(mine), len(written))
        self.assertGreater(len(seen), 10)
        for name in ARRAYS:
            with self.subTest(engine=engine, array=name):
                a, b = getattr(mine, name), getattr(written, name)
                self.assertEqual(a.shape, b.shape)
                self.assertLessEqual(float(numpy.max(numpy.abs(a - b))), 1e-12 * largest(b))
        self.assertEqual(mine.status, written.status)
        self.assertEqual(mine.branches, written.branches)

    def test_the_fe_cube_returns_the_command_lines_curve(self):
        self.agrees_with_the_command_line("continuum")

    def test_the_dem_returns_the_command_lines_curve_from_its_prepared_specimen(self):
        self.agrees_with_the_command_line("dem")


if __name__ == "__main__":
    unittest.main(verbosity=2)
