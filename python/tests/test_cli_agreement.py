"""The issue's done-when: `import geocomp` runs the demo's material-point case in-process and
returns the command line's curve to round-off."""
import sys
import unittest

import numpy

import geocomp
from support import ARRAYS, DEMO, cli_results, largest


class TheInProcessMaterialPointRun(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder, path = cli_results("material-point")
        cls.file = geocomp.read_results(path)
        cls.response = geocomp.run(geocomp.read_case(DEMO), "material-point", output=cls.folder.name)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_returns_the_curve_the_command_line_wrote_to_round_off(self):
        self.assertGreater(len(self.response), 10)
        self.assertEqual(len(self.response), len(self.file))
        identical = True
        for name in ARRAYS:
            mine, theirs = getattr(self.response, name), getattr(self.file, name)
            with self.subTest(array=name):
                self.assertEqual(mine.shape, theirs.shape)
                difference = float(numpy.max(numpy.abs(mine - theirs))) if mine.size else 0.0
                self.assertLessEqual(difference, 1e-12 * largest(theirs), f"{name}: max |difference| {difference}")
                identical = identical and numpy.array_equal(mine, theirs)
        print(f"\n  {len(self.response)} samples; every array bit-identical: {identical}", file=sys.stderr)

    def test_returns_the_command_lines_extras_branches_and_stages(self):
        self.assertEqual(sorted(self.response.extras), sorted(self.file.extras))
        for name, column in self.file.extras.items():
            with self.subTest(extra=name):
                numpy.testing.assert_allclose(self.response.extras[name], column, rtol=0, atol=1e-12 * largest(column))
        self.assertEqual(self.response.stage_names, self.file.stage_names)
        self.assertEqual(self.response.stage_end_reasons, self.file.stage_end_reasons)
        self.assertEqual(len(self.response.branches), len(self.file.branches))
        self.assertGreater(len(self.response.branches), 0)
        for mine, theirs in zip(self.response.branches, self.file.branches):
            self.assertEqual(mine, theirs)

    def test_reports_the_status_the_command_line_wrote(self):
        self.assertEqual(self.response.status, self.file.status)
        self.assertEqual(self.response.engine, self.file.engine)


if __name__ == "__main__":
    unittest.main(verbosity=2)
