"""geocomp.pair runs the command line's `pair` in-process: the same results files, the same
metrics and verdict, a report; progress per engine; reuse; a busy output folder refused."""
import json
import os
import pathlib
import sys
import tempfile
import unittest

import numpy

import geocomp
from support import ARRAYS, DEMO, SOURCE_DIR, run_cli

ENGINES = ["continuum", "material-point"]


class PairFromPython(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.chdir(SOURCE_DIR)
        cls.folder = tempfile.TemporaryDirectory(prefix="geocomp-python-pair-")
        root = pathlib.Path(cls.folder.name)
        case = geocomp.read_case(DEMO)  # the demo's continuum engines: seconds, not minutes
        case.set("engines", ", ".join(ENGINES))
        cls.case_file = root / "pair.prm"
        cls.case_file.write_text(case.text)
        cls.cli_dir, cls.py_dir = root / "cli", root / "python"
        done = run_cli("pair", str(cls.case_file), "--output", str(cls.cli_dir), "--force")
        if done.returncode != 0:
            raise AssertionError(f"geocomp pair failed ({done.returncode}): {done.stderr}")
        cls.seen = []
        cls.result = geocomp.pair(geocomp.read_case(str(cls.case_file)), output=str(cls.py_dir), force=True,
                                  progress=cls.seen.append)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_writes_the_command_lines_results_files_bit_for_bit(self):
        self.assertEqual(sorted(self.result["responses"]), sorted(ENGINES))
        for engine in ENGINES:
            written = geocomp.read_results(str(self.cli_dir / (engine + ".h5")))
            mine = geocomp.read_results(str(self.py_dir / (engine + ".h5")))
            returned = self.result["responses"][engine]
            self.assertGreater(len(written), 10)
            for name in ARRAYS:
                with self.subTest(engine=engine, array=name):
                    self.assertTrue(numpy.array_equal(getattr(mine, name), getattr(written, name)))
                    self.assertTrue(numpy.array_equal(getattr(returned, name), getattr(written, name)))
            self.assertEqual(mine.status, "complete")
            self.assertIn("geocomp.pair", mine.meta["command"])

    def test_returns_the_metrics_and_verdict_the_command_line_reported(self):
        reported = json.loads((self.cli_dir / "report" / "metrics.json").read_text())
        self.assertEqual(self.result["metrics"], reported)
        self.assertEqual(self.result["metrics"], json.loads((self.py_dir / "report" / "metrics.json").read_text()))
        self.assertTrue(self.result["complete"])
        self.assertTrue(pathlib.Path(self.result["report"]).is_file())
        print(f"\n  metrics of {sorted(reported.get('engines', reported))} identical to the command line's",
              file=sys.stderr)

    def test_reports_progress_of_every_engine(self):
        engines = {p["engine"] for p in self.seen}
        self.assertEqual(engines, set(ENGINES))
        self.assertTrue(all(0.0 <= p["stage_fraction"] <= 1.0 + 1e-9 for p in self.seen))

    def test_reuses_up_to_date_results_without_running_again(self):
        seen = []
        again = geocomp.pair(geocomp.read_case(str(self.case_file)), output=str(self.py_dir), progress=seen.append)
        self.assertEqual(seen, [])  # nothing ran
        self.assertEqual(again["metrics"], self.result["metrics"])

    def test_refuses_an_output_folder_another_run_holds_and_runs_nothing(self):
        import fcntl
        busy = self.py_dir.parent / "busy"
        busy.mkdir()
        with open(busy / ".geocomp.lock", "w") as held:
            fcntl.flock(held, fcntl.LOCK_EX)  # what a running `geocomp pair` holds
            held.write("process 12345 on another host: geocomp pair other.prm\n")
            held.flush()
            seen = []
            with self.assertRaises(geocomp.CaseError) as raised:
                geocomp.pair(geocomp.read_case(str(self.case_file)), output=str(busy), progress=seen.append)
        self.assertIn("in use by another run", str(raised.exception))
        self.assertIn("process 12345", str(raised.exception))
        self.assertEqual(seen, [])
        self.assertEqual(sorted(p.name for p in busy.iterdir()), [".geocomp.lock"])

    def test_stops_when_the_progress_callback_raises_and_raises_it_again(self):
        class Enough(Exception):
            pass

        def stop(p):
            if p["time"] > 0:
                raise Enough()
        with self.assertRaises(Enough):
            geocomp.pair(geocomp.read_case(str(self.case_file)), output=str(self.py_dir.parent / "stopped"),
                         force=True, progress=stop)


if __name__ == "__main__":
    unittest.main(verbosity=2)
