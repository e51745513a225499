"""The package's metadata allows Python 3.9, so every source file must be 3.9 syntax (no
`match`, no parenthesised context managers, ...): checked with the parser's feature_version."""
import ast
import unittest
from pathlib import Path

import tlmhub

PACKAGE = Path(tlmhub.__file__).resolve().parent


class Sources(unittest.TestCase):
    def test_every_module_is_python_3_9_syntax(self):
        files = sorted(PACKAGE.glob("*.py"))
        self.assertGreater(len(files), 5, f"the package's modules under {PACKAGE}")
        for path in files:
            with self.subTest(module=path.name):
                ast.parse(path.read_text(encoding="utf-8"), filename=str(path), feature_version=(3, 9))

    def test_the_parser_refuses_newer_syntax(self):
        with self.assertRaises(SyntaxError):   # so the check above can fail
            ast.parse("match x:\n    case 1:\n        pass\n", feature_version=(3, 9))


if __name__ == "__main__":
    unittest.main()
