"""Simulation results and study tables, kept as the server's CSV bytes.

The server writes numbers as `%.17g`, which reads back as the same float64, so parsing its
CSV loses nothing, and keeping the bytes makes `to_csv()` exactly the server's file.

NumPy and pandas are optional: columns are lists without NumPy, and `to_numpy`, `grid` and
`to_pandas` raise ImportError naming what to install. pandas is imported only when
`to_pandas` is called (it takes a while to import)."""
from __future__ import annotations

import html
import math
import os
import re
from typing import Any, Mapping, Sequence

try:
    import numpy
except ImportError:
    numpy = None

NUMPY_MISSING = ("this needs NumPy, which is not installed: pip install 'tlmhub[numpy]' "
                 "(or apt-get install python3-numpy)")
PANDAS_MISSING = ("this needs pandas, which is not installed: pip install 'tlmhub[pandas]' "
                  "(or apt-get install python3-pandas)")

# An output column of a study's table is `Variable:value` (docs/studies.md, "outputs").
OUTPUT_COLUMN = re.compile(r":(final|min|max|mean)$")
# How many variables or rows `_repr_html_` shows before it says how many more there are.
HTML_ROWS = 20


def _pandas(what: str) -> Any:
    """The pandas module, imported on first use; ImportError naming `what` and the install."""
    try:
        import pandas
    except ImportError:
        raise ImportError(f"{what}: {PANDAS_MISSING}") from None
    return pandas


def _number_html(value: Any) -> str:
    """A cell of an HTML summary: numbers to 6 significant digits, None empty."""
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.6g}"
    return html.escape(str(value))


def _html_table(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    head = "".join(f"<th>{html.escape(name)}</th>" for name in header)
    body = "".join("<tr>" + "".join(f"<td>{_number_html(v)}</td>" for v in row) + "</tr>"
                   for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _range(column: Any) -> tuple[Any, Any]:
    """(min, max) of a column's numbers that are not NaN; (None, None) when there are none."""
    if numpy is not None:
        values = numpy.asarray(column, dtype=float)
        finite = values[~numpy.isnan(values)]
        return (float(finite.min()), float(finite.max())) if finite.size else (None, None)
    finite = [v for v in column if not math.isnan(v)]
    return (min(finite), max(finite)) if finite else (None, None)


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

    Columns are NumPy arrays when NumPy is installed, lists of floats otherwise. `units`
    maps variables to their units: a job's results (`client.run`, `jobs.results`) have them
    from `GET /jobs/{id}/variables`; a Result made from CSV alone knows none."""

    def __init__(self, csv: bytes, units: Mapping[str, str] | None = None):
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
        self._units = {name: str(unit) for name, unit in (units or {}).items() if name in self._names}

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

    @property
    def units(self) -> dict[str, str]:
        """Each variable's unit, of those this result knows (see the class)."""
        return dict(self._units)

    def to_csv(self, path: str | os.PathLike | None = None) -> bytes:
        """The server's CSV, byte for byte; also written to `path` when one is given."""
        return _write(self._csv, path)

    def to_numpy(self) -> Any:
        """A 2-D array, one row per sample, columns `time` and then `names`."""
        if numpy is None:
            raise ImportError("Result.to_numpy: " + NUMPY_MISSING)
        return numpy.column_stack([self._columns["time"]] + [self._columns[n] for n in self._names])

    def to_pandas(self) -> Any:
        """A pandas DataFrame: the time as its index (named `time`), one float64 column per
        variable, in `names`' order; `attrs["units"]` is `units` (the units known)."""
        pandas = _pandas("Result.to_pandas")
        index = pandas.Index(numpy.asarray(self._columns["time"], dtype=float), name="time")
        frame = pandas.DataFrame({name: numpy.asarray(self._columns[name], dtype=float) for name in self._names},
                                 index=index, columns=self._names)
        frame.attrs["units"] = self.units
        return frame

    def __repr__(self) -> str:
        return f"<Result {len(self)} samples of {len(self._names)} variables>"

    def _repr_html_(self) -> str:
        """Jupyter's view: the size and time span, then per variable its unit (a column
        only when the result knows units) and its first, final, least and greatest value."""
        time = self._columns["time"]
        span = f", time {time[0]:.6g} to {time[-1]:.6g} s" if len(time) else ""
        units = ["unit"] if self._units else []
        rows = []
        for name in self._names[:HTML_ROWS]:
            column = self._columns[name]
            first, final = (float(column[0]), float(column[-1])) if len(column) else (None, None)
            rows.append([name] + [self._units.get(name, "")] * len(units) + [first, final, *_range(column)])
        more = len(self._names) - HTML_ROWS
        return (f"<div><p><b>Result</b>: {len(self)} samples of {len(self._names)} variables{span}</p>"
                + _html_table(["variable", *units, "first", "final", "min", "max"], rows)
                + (f"<p>... and {more} more variables</p>" if more > 0 else "") + "</div>")


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

    def _at(self, column: str) -> int:
        try:
            return self.columns.index(column)
        except ValueError:
            raise KeyError(f"no column {column!r} in this table") from None

    def __getitem__(self, column: str) -> Any:
        at = self._at(column)
        return _column([math.nan if row[at] is None else row[at] for row in self.rows])

    @property
    def parameters(self) -> list[str]:
        """The parameter columns: those after `run` and `ok` that are neither an output
        (`Variable:final|min|max|mean`) nor `objective`."""
        return [c for c in self.columns
                if c not in ("run", "ok", "objective") and not OUTPUT_COLUMN.search(c)]

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

    def to_pandas(self) -> Any:
        """A pandas DataFrame of the rows: indexed by the run number (named `run`) when the
        table has a `run` column, the other columns as `columns`; `ok` as 0/1 integers, the
        rest float64 with None as NaN. `attrs["errors"]` maps a failed run's number to its
        message."""
        pandas = _pandas("Table.to_pandas")
        data = {}
        for at, name in enumerate(self.columns):
            values = [row[at] for row in self.rows]
            if name in ("run", "ok"):
                data[name] = numpy.array([int(v) for v in values], dtype="int64")
            else:
                data[name] = numpy.array([math.nan if v is None else v for v in values], dtype=float)
        index = pandas.Index(data.pop("run"), name="run") if "run" in data else None
        frame = pandas.DataFrame(data, index=index, columns=[c for c in self.columns if c != "run"])
        frame.attrs["errors"] = {int(run) if str(run).isdigit() else run: message
                                 for run, message in self.errors.items()}
        return frame

    def grid(self, column: str, parameters: Sequence[str] | None = None) -> "Grid":
        """`column` of a grid sweep as an N-D array with an axis per swept parameter.

        `parameters`: the axes, by default `self.parameters` in the table's order (the
        sweep's: the first varies slowest). Each axis holds its parameter's distinct values
        in the order the runs first took them (a grid's order: a list as given, from-to
        ascending). A cell whose run is missing (not run yet, a cancelled study) or failed is
        NaN. ValueError when two runs have the same values of `parameters` (a random or list
        sweep is no grid)."""
        if numpy is None:
            raise ImportError("Table.grid: " + NUMPY_MISSING)
        at = self._at(column)
        names = list(self.parameters if parameters is None else parameters)
        if not names:
            raise ValueError("this table has no parameter columns to make a grid of")
        where = [self._at(name) for name in names]
        positions: list[dict[Any, int]] = [{} for _ in names]
        for row in self.rows:
            for axis, p in zip(positions, where):
                axis.setdefault(row[p], len(axis))
        shape = tuple(len(axis) for axis in positions)
        values = numpy.full(shape, math.nan)
        run_at = self.columns.index("run") if "run" in self.columns else None
        taken: dict[tuple[int, ...], Any] = {}
        for number, row in enumerate(self.rows):
            cell = tuple(axis[row[p]] for axis, p in zip(positions, where))
            run = number if run_at is None else row[run_at]
            if cell in taken:
                raise ValueError(f"runs {taken[cell]} and {run} have the same values of {', '.join(names)}: "
                                 "not a grid of these parameters")
            taken[cell] = run
            values[cell] = math.nan if row[at] is None else row[at]
        axes = {name: numpy.array(list(axis), dtype=float) for name, axis in zip(names, positions)}
        return Grid(column, names, axes, values)

    def __repr__(self) -> str:
        return f"<Table {len(self.rows)} runs x {len(self.columns)} columns>"

    def _repr_html_(self) -> str:
        """Jupyter's view: the size, then the first rows (failed outputs empty)."""
        failed = len(self.errors)
        more = len(self.rows) - HTML_ROWS
        return (f"<div><p><b>Table</b>: {len(self.rows)} runs x {len(self.columns)} columns"
                + (f", {failed} failed" if failed else "") + "</p>"
                + _html_table(self.columns, self.rows[:HTML_ROWS])
                + (f"<p>... and {more} more runs</p>" if more > 0 else "") + "</div>")


class Grid:
    """A grid sweep's output as an N-D array (`Table.grid`): `values[i, j, ...]` is the run
    with `axes[names[0]][i]`, `axes[names[1]][j]`, ...; NaN where that run is missing or
    failed. `column` is the table column it holds."""

    def __init__(self, column: str, names: list[str], axes: dict[str, Any], values: Any):
        self.column = column
        self.names = names
        self.axes = axes
        self.values = values

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(self.values.shape)

    def __repr__(self) -> str:
        sizes = " x ".join(f"{len(self.axes[name])} {name}" for name in self.names)
        return f"<Grid {self.column} over {sizes}>"


def variables_query(variables: Sequence[str] | str | None) -> str | None:
    """The `variables=a,b` query value of the results endpoints."""
    if variables is None or isinstance(variables, str):
        return variables
    return ",".join(variables)
