"""Results where analysts want them: `Result.to_pandas()`, `Table.to_pandas()`, a grid
sweep's output as an N-D array (`Table.grid`) and the HTML views Jupyter shows.

pandas is optional, as NumPy is: the ctest of each venv says whether it must be there
(TLMHUB_EXPECT_PANDAS), so a venv that lost pandas fails (the DataFrame tests then raise the
ImportError) instead of skipping them, and the venv without it checks the ImportError's
install hint."""
import html
import importlib.util
import json
import math
import subprocess
import sys
import unittest
import urllib.request

import tlmhub
from harness import ADMIN_PASSWORD, REPO, Server, expectation, shared_model

server: Server
HAVE_PANDAS = expectation("TLMHUB_EXPECT_PANDAS", "pandas")
HAVE_NUMPY = expectation("TLMHUB_EXPECT_NUMPY", "numpy")
POSITION = "Mass#P2#Position"
SHORT = {"stop": 0.3, "log_samples": 100}
# tests/server/data/RoundDivide.hmf: Divide#out#Value = Divide.in1 / round(Round.in); a run
# with round(Round.in) = 0 fails (division by zero).
DIVIDER = REPO / "tests" / "server" / "data" / "RoundDivide.hmf"
QUOTIENT = "Divide#out#Value:final"


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


def raw_json(client: tlmhub.Client, path: str) -> dict:
    request = urllib.request.Request(client.url + path,
                                     headers={"Authorization": "Bearer " + client._transport.token})
    with urllib.request.urlopen(request) as response:
        return json.load(response)


class Environment(unittest.TestCase):
    def test_the_environment_is_the_expected_one(self):
        installed = importlib.util.find_spec("pandas") is not None
        self.assertEqual(installed, HAVE_PANDAS,
                         "TLMHUB_EXPECT_PANDAS says pandas must " + ("" if HAVE_PANDAS else "not ")
                         + "be installed here (apt-get install python3-pandas)")

    def test_importing_tlmhub_does_not_import_pandas(self):
        imported = subprocess.run([sys.executable, "-c", "import sys, tlmhub; print('pandas' in sys.modules)"],
                                  capture_output=True, text=True, check=True)
        self.assertEqual(imported.stdout.strip(), "False")


class ResultFrames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.job = cls.client.run(shared_model(), wait=False, **SHORT).wait()
        cls.result = cls.job.results()

    @unittest.skipUnless(HAVE_PANDAS, "DataFrames: the venv with pandas")
    def test_a_results_frame_is_to_numpy_indexed_by_time(self):
        frame = self.result.to_pandas()
        array = self.result.to_numpy()
        self.assertEqual(frame.shape, (100, len(self.result.names)))
        self.assertEqual(frame.index.name, "time")
        self.assertEqual(frame.index.tolist(), self.result.time.tolist())
        self.assertEqual(list(frame.columns), self.result.names)
        for at, name in enumerate(self.result.names, start=1):
            with self.subTest(variable=name):
                self.assertEqual(str(frame[name].dtype), "float64")
                self.assertEqual(frame[name].tolist(), array[:, at].tolist())
        self.assertEqual(frame[POSITION].iloc[-1], self.result[POSITION][-1])
        # Fetched with the results (GET /jobs/{id}/variables: the CSV carries none).
        self.assertEqual(frame.attrs["units"], self.result.units)
        self.assertEqual(frame.attrs["units"][POSITION], "m")

    @unittest.skipUnless(HAVE_PANDAS, "DataFrames: the venv with pandas")
    def test_units_a_result_knows_are_in_the_frames_attrs(self):
        # The server's JSON form has each variable's unit; a Result made with them keeps
        # those of its own variables.
        reply = raw_json(self.client, f"/jobs/{self.job.id}/results?format=json")
        units = {variable["name"]: variable["unit"] for variable in reply["variables"]}
        self.assertEqual(units[POSITION], "m")
        result = tlmhub.Result(self.result.to_csv(), units={**units, "Nothing#P1#x": "s"})
        self.assertEqual(result.units, units)
        frame = result.to_pandas()
        self.assertEqual(frame.attrs["units"], units)
        self.assertEqual(frame.attrs["units"][POSITION], "m")

    @unittest.skipIf(HAVE_PANDAS, "to_pandas' ImportError: the venv without pandas")
    def test_to_pandas_without_pandas_says_what_to_install(self):
        with self.assertRaises(ImportError) as caught:
            self.result.to_pandas()
        message = str(caught.exception)
        self.assertTrue(message.startswith("Result.to_pandas: "), message)
        for hint in ("pandas", "pip install 'tlmhub[pandas]'", "apt-get install python3-pandas"):
            self.assertIn(hint, message)

    def test_html_view_lists_the_variables_with_their_values(self):
        view = self.result._repr_html_()
        self.assertTrue(view.startswith("<div>") and view.endswith("</div>"), view[:200])
        self.assertIn("<th>variable</th><th>unit</th><th>first</th>", view)
        self.assertIn("<th>variable</th><th>first</th>",                  # no units known: no unit column
                      tlmhub.Result(self.result.to_csv())._repr_html_())
        self.assertIn(f"100 samples of {len(self.result.names)} variables, time 0 to 0.3 s", view)
        self.assertEqual(view.count("<tr>"), 21)                     # the header and 20 variables
        self.assertIn(f"... and {len(self.result.names) - 20} more variables", view)
        position = self.job.results(variables=[POSITION])[POSITION]
        self.assertIn(f"<td>{POSITION}</td><td>m</td><td>{position[0]:.6g}</td><td>{position[-1]:.6g}</td>"
                      f"<td>{min(position):.6g}</td><td>{max(position):.6g}</td>",
                      self.job.results(variables=[POSITION])._repr_html_())

    def test_html_view_escapes_names(self):
        result = tlmhub.Result(b"time,A<b>&C#P1#x\n0,1\n0.5,2\n", units={"A<b>&C#P1#x": "<m>"})
        view = result._repr_html_()
        self.assertNotIn("A<b>", view)
        self.assertIn("<th>variable</th><th>unit</th><th>first</th>", view)
        self.assertIn("<td>A&lt;b&gt;&amp;C#P1#x</td><td>&lt;m&gt;</td><td>1</td><td>2</td><td>1</td><td>2</td>", view)


class Grids(unittest.TestCase):
    """A 3 x 4 grid of the Position Servo's gains, and a 3 x 4 grid of RoundDivide whose
    runs with Round.in = 0 fail."""

    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.servo = cls.client.sweep(
            shared_model(), parameters={"GainP.k": [0.01, 0.02, 0.03, 0.04], "GainI.k": [0, 0.0005, 0.001]},
            outputs=[POSITION], values=["final", "max"], **SHORT).table()
        # Parameters in name order: Divide.in1 (3 values), then Round.in (4).
        cls.divider = cls.client.sweep(
            DIVIDER, parameters={"Round.in": [1, 0, 2, 4], "Divide.in1": [3, 1, 2]},
            outputs=["Divide#out#Value"]).table()

    def test_the_tables_are_the_sweeps(self):
        self.assertEqual(len(self.servo), 12)
        self.assertEqual(self.servo.parameters, ["GainI.k", "GainP.k"])
        self.assertEqual(len(self.divider), 12)
        self.assertEqual(self.divider.parameters, ["Divide.in1", "Round.in"])
        self.assertEqual(sorted(int(run) for run in self.divider.errors), [1, 5, 9])

    @unittest.skipUnless(HAVE_NUMPY, "grid: the venv with NumPy")
    def test_a_grid_has_an_axis_per_parameter_and_each_cell_is_its_run(self):
        grid = self.servo.grid(f"{POSITION}:max")
        self.assertEqual(grid.shape, (3, 4))
        self.assertEqual(grid.values.shape, (3, 4))
        self.assertEqual(grid.names, ["GainI.k", "GainP.k"])
        self.assertEqual({name: axis.tolist() for name, axis in grid.axes.items()},
                         {"GainI.k": [0, 0.0005, 0.001], "GainP.k": [0.01, 0.02, 0.03, 0.04]})
        at = self.servo.columns.index(f"{POSITION}:max")
        for row in self.servo.rows:
            i = grid.axes["GainI.k"].tolist().index(row[2])
            j = grid.axes["GainP.k"].tolist().index(row[3])
            self.assertEqual(grid.values[i, j], row[at])
        self.assertEqual(len({float(v) for v in grid.values.flat}), 12)

    @unittest.skipUnless(HAVE_NUMPY, "grid: the venv with NumPy")
    def test_a_grid_keeps_the_sweeps_order_and_failed_runs_are_nan(self):
        grid = self.divider.grid(QUOTIENT)
        self.assertEqual(grid.shape, (3, 4))
        self.assertEqual(grid.axes["Divide.in1"].tolist(), [3, 1, 2])   # as the lists gave them
        self.assertEqual(grid.axes["Round.in"].tolist(), [1, 0, 2, 4])
        for i, in1 in enumerate([3, 1, 2]):
            for j, value in enumerate([1, 0, 2, 4]):
                with self.subTest(in1=in1, round_in=value):
                    if value == 0:
                        self.assertTrue(math.isnan(grid.values[i, j]))
                    else:
                        self.assertEqual(grid.values[i, j], in1 / value)

    @unittest.skipUnless(HAVE_NUMPY, "grid: the venv with NumPy")
    def test_a_missing_run_is_nan(self):
        rows = [row for row in self.servo.rows if row[0] != 5]
        table = tlmhub.Table({"columns": self.servo.columns, "rows": rows}, lambda: b"")
        grid = table.grid(f"{POSITION}:final")
        self.assertEqual(grid.shape, (3, 4))
        self.assertTrue(math.isnan(grid.values[1, 1]))            # run 5: the 2nd GainI.k, 2nd GainP.k
        self.assertEqual(sum(math.isnan(v) for v in grid.values.flat), 1)

    @unittest.skipUnless(HAVE_NUMPY, "grid: the venv with NumPy")
    def test_parameters_that_do_not_make_a_grid_are_refused(self):
        with self.assertRaises(ValueError) as caught:   # each GainP.k has three runs
            self.servo.grid(f"{POSITION}:final", parameters=["GainP.k"])
        self.assertIn("not a grid", str(caught.exception))
        with self.assertRaises(KeyError):
            self.servo.grid("Mass#P2#Nothing:final")

    @unittest.skipIf(HAVE_NUMPY, "grid's ImportError: the venv without NumPy")
    def test_grid_without_numpy_says_what_to_install(self):
        with self.assertRaises(ImportError) as caught:
            self.servo.grid(f"{POSITION}:final")
        self.assertIn("tlmhub[numpy]", str(caught.exception))

    @unittest.skipUnless(HAVE_PANDAS, "DataFrames: the venv with pandas")
    def test_a_tables_frame_is_indexed_by_run_with_failed_outputs_nan(self):
        frame = self.divider.to_pandas()
        self.assertEqual(frame.index.name, "run")
        self.assertEqual(frame.index.tolist(), [row[0] for row in self.divider.rows])
        self.assertEqual(list(frame.columns), self.divider.columns[1:])
        self.assertEqual(str(frame["ok"].dtype), "int64")
        self.assertEqual(frame["ok"].tolist(), [0 if row[3] == 0 else 1 for row in self.divider.rows])
        for row in self.divider.rows:
            with self.subTest(run=row[0]):
                self.assertEqual(frame.loc[row[0], "Divide.in1"], row[2])
                self.assertEqual(frame.loc[row[0], "Round.in"], row[3])
                if row[3] == 0:
                    self.assertIsNone(row[4])
                    self.assertTrue(math.isnan(frame.loc[row[0], QUOTIENT]))
                else:
                    self.assertEqual(frame.loc[row[0], QUOTIENT], row[2] / row[3])
        self.assertEqual(sorted(frame.attrs["errors"]), [1, 5, 9])
        self.assertIn("Division by zero", frame.attrs["errors"][1])

    @unittest.skipUnless(HAVE_PANDAS, "DataFrames: the venv with pandas")
    def test_a_tables_frame_equals_to_numpy(self):
        frame = self.servo.to_pandas()
        array = self.servo.to_numpy()
        self.assertEqual(frame.index.tolist(), array[:, 0].tolist())
        for at, name in enumerate(self.servo.columns[1:], start=1):
            self.assertEqual(frame[name].tolist(), array[:, at].tolist())

    @unittest.skipIf(HAVE_PANDAS, "to_pandas' ImportError: the venv without pandas")
    def test_table_to_pandas_without_pandas_says_what_to_install(self):
        with self.assertRaises(ImportError) as caught:
            self.servo.to_pandas()
        self.assertTrue(str(caught.exception).startswith("Table.to_pandas: "))
        self.assertIn("pip install 'tlmhub[pandas]'", str(caught.exception))

    def test_html_view_shows_the_size_and_the_rows(self):
        view = self.divider._repr_html_()
        self.assertIn("12 runs x 5 columns, 3 failed", view)
        self.assertIn("<th>Divide#out#Value:final</th>", view)
        self.assertEqual(view.count("<tr>"), 13)                       # header and 12 runs
        self.assertIn("<td>1</td><td>0</td><td>3</td><td>0</td><td></td></tr>", view)   # run 1 failed


if __name__ == "__main__":
    unittest.main()
