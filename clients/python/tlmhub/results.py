"""Simulation results and study tables, kept as the server's CSV bytes.

The server writes numbers as `%.17g`, which reads back as the same float64, so parsing its
CSV loses nothing, and keeping the bytes makes `to_csv()` exactly the server's file."""
from __future__ import annotations

import math
import os
from typing import Any, Sequence

try:
    import numpy
except ImportError:
    numpy = None

NUMPY_MISSING = ("this needs NumPy, which is not installed: pip install 'tlmhub[numpy]' "
                 "(or apt-get install python3-numpy)")


def _column(values: list[float]) -> Any:
    """A column as a NumPy array when NumPy is installed, else as the list itself."""
    return numpy.array(values, dtype=float) if numpy is not None else values


def _write(data: bytes, path: str | os.PathLike | None) -> bytes:
    if path is not None:
        with open(path, "wb") as out:
            out.write(data)
    return data


class Result:
    """One simulation's logged variables: `result["Mass#P2#Position"]`, `result.time`.

    Columns are NumPy arrays when NumPy is installed, lists of floats otherwise."""

    def __init__(self, csv: bytes):
        self._csv = csv
        lines = csv.decode().splitlines()
        if not lines:
            raise ValueError("empty results CSV")
        header = lines[0].split(",")
        values: list[list[float]] = [[] for _ in header]
        for line in lines[1:]:
            for column, field in zip(values, line.split(",")):
                column.append(float(field))
        self._names = header[1:]
        self._columns = {name: _column(column) for name, column in zip(header, values)}

    @property
    def time(self) -> Any:
        return self._columns["time"]

    @property
    def names(self) -> list[str]:
        """The variables (`Comp#Port#Variable`), in the CSV's order, without `time`."""
        return list(self._names)

    def __getitem__(self, name: str) -> Any:
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"no variable {name!r} in this result") from None

    def __contains__(self, name: object) -> bool:
        return name in self._columns

    def __len__(self) -> int:
        """The number of logged samples."""
        return len(self._columns["time"])

    def to_csv(self, path: str | os.PathLike | None = None) -> bytes:
        """The server's CSV, byte for byte; also written to `path` when one is given."""
        return _write(self._csv, path)

    def to_numpy(self) -> Any:
        """A 2-D array, one row per sample, columns `time` and then `names`."""
        if numpy is None:
            raise ImportError("Result.to_numpy: " + NUMPY_MISSING)
        return numpy.column_stack([self._columns["time"]] + [self._columns[n] for n in self._names])

    def __repr__(self) -> str:
        return f"<Result {len(self)} samples of {len(self._names)} variables>"


class Table:
    """A study's results table: one row per finished run (docs/studies.md, "The results
    table"). `table["Mass#P2#Position:final"]` is a column; a failed run's empty outputs are
    None in `rows` and NaN in columns."""

    def __init__(self, data: dict[str, Any], csv_source: Any):
        self.columns: list[str] = list(data["columns"])
        self.rows: list[list[Any]] = [list(row) for row in data["rows"]]
        self.errors: dict[str, str] = dict(data.get("errors") or {})
        self._csv_source = csv_source
        self._csv: bytes | None = None

    def __getitem__(self, column: str) -> Any:
        try:
            at = self.columns.index(column)
        except ValueError:
            raise KeyError(f"no column {column!r} in this table") from None
        return _column([math.nan if row[at] is None else row[at] for row in self.rows])

    def __len__(self) -> int:
        return len(self.rows)

    def to_csv(self, path: str | os.PathLike | None = None) -> bytes:
        """The server's CSV of the table, byte for byte (fetched once, on first use)."""
        if self._csv is None:
            self._csv = self._csv_source()
        return _write(self._csv, path)

    def to_numpy(self) -> Any:
        """A 2-D float array of the rows (None as NaN), columns as `columns`."""
        if numpy is None:
            raise ImportError("Table.to_numpy: " + NUMPY_MISSING)
        return numpy.array([[math.nan if v is None else v for v in row] for row in self.rows],
                           dtype=float).reshape(len(self.rows), len(self.columns))

    def __repr__(self) -> str:
        return f"<Table {len(self.rows)} runs x {len(self.columns)} columns>"


def variables_query(variables: Sequence[str] | str | None) -> str | None:
    """The `variables=a,b` query value of the results endpoints."""
    if variables is None or isinstance(variables, str):
        return variables
    return ",".join(variables)
