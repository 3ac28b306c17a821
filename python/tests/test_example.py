"""python/examples/demo_overlay.py draws the demo's overlay from results files."""
import os
import subprocess
import sys
import tempfile
import unittest

from support import DEMO, SOURCE_DIR, run_cli


class TheOverlayExample(unittest.TestCase):
    def test_writes_a_png_of_the_curves_in_a_results_folder(self):
        with tempfile.TemporaryDirectory(prefix="geocomp-python-") as folder:
            done = run_cli("material-point", DEMO, "--output", folder, "--force")
            self.assertEqual(done.returncode, 0, done.stderr)
            png = os.path.join(folder, "overlay.png")
            script = os.path.join(SOURCE_DIR, "python/examples/demo_overlay.py")
            drawn = subprocess.run([sys.executable, script, folder, png], capture_output=True, text=True, timeout=300)
            self.assertEqual(drawn.returncode, 0, drawn.stderr)
            self.assertIn("material-point", drawn.stdout)
            with open(png, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            self.assertGreater(os.path.getsize(png), 10000)

    def test_says_what_is_missing_when_the_folder_has_no_results(self):
        with tempfile.TemporaryDirectory(prefix="geocomp-python-") as folder:
            script = os.path.join(SOURCE_DIR, "python/examples/demo_overlay.py")
            drawn = subprocess.run([sys.executable, script, folder], capture_output=True, text=True, timeout=300)
            self.assertNotEqual(drawn.returncode, 0)
            self.assertIn("geocomp pair cases/demo.prm", drawn.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
