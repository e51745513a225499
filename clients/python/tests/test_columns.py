"""Columns are NumPy arrays where NumPy is installed and lists of floats where it is not; the
ctest of each venv says which it must be (TLMHUB_EXPECT_NUMPY), so a venv that lost or gained
NumPy fails instead of testing the other case twice."""
import importlib.util
import unittest

import tlmhub
from harness import ADMIN_PASSWORD, Server, expectation, shared_model

server: Server
HAVE_NUMPY = expectation("TLMHUB_EXPECT_NUMPY", "numpy")


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


class Columns(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.result = cls.client.run(shared_model(), stop=0.3, log_samples=100)

    def test_the_environment_is_the_expected_one(self):
        installed = importlib.util.find_spec("numpy") is not None
        self.assertEqual(installed, HAVE_NUMPY)

    @unittest.skipUnless(HAVE_NUMPY, "columns as NumPy arrays: the venv with NumPy")
    def test_columns_are_numpy_arrays(self):
        import numpy
        position = self.result["Mass#P2#Position"]
        self.assertIsInstance(position, numpy.ndarray)
        self.assertEqual(position.dtype, numpy.float64)
        self.assertEqual(position.shape, (100,))
        self.assertIsInstance(self.result.time, numpy.ndarray)

    @unittest.skipUnless(HAVE_NUMPY, "to_numpy: the venv with NumPy")
    def test_to_numpy_is_time_then_every_variable(self):
        table = self.result.to_numpy()
        self.assertEqual(table.shape, (100, 1 + len(self.result.names)))
        at = 1 + self.result.names.index("Mass#P2#Position")
        self.assertEqual(table[:, at].tolist(), self.result["Mass#P2#Position"].tolist())
        self.assertEqual(table[:, 0].tolist(), self.result.time.tolist())

    @unittest.skipIf(HAVE_NUMPY, "columns as lists: the venv without NumPy")
    def test_columns_are_lists_of_floats(self):
        position = self.result["Mass#P2#Position"]
        self.assertIsInstance(position, list)
        self.assertEqual(len(position), 100)
        self.assertTrue(all(isinstance(v, float) for v in position))
        self.assertIsInstance(self.result.time, list)

    @unittest.skipIf(HAVE_NUMPY, "to_numpy's ImportError: the venv without NumPy")
    def test_to_numpy_says_what_to_install(self):
        with self.assertRaises(ImportError) as caught:
            self.result.to_numpy()
        self.assertIn("NumPy", str(caught.exception))
        self.assertIn("tlmhub[numpy]", str(caught.exception))

    def test_unknown_variable_is_a_key_error(self):
        with self.assertRaises(KeyError):
            self.result["Mass#P2#NoSuchVariable"]


if __name__ == "__main__":
    unittest.main()
