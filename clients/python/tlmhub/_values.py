"""Values a request carries, checked before it is sent so that a mistake is named by the
parameter it is in: NaN and infinities are refused (JSON has no such numbers), NumPy and
other numeric scalars become plain floats, a text (an expression or a system parameter's
name) passes as it is where the server evaluates one."""
from __future__ import annotations

import math
import numbers
from typing import Any, Mapping, Sequence


def number(what: str, value: Any) -> float:
    """`value` as a finite float; ValueError or TypeError naming `what` otherwise."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{what}: {value!r} is not a number")
    result = float(value)
    if not math.isfinite(result):
        raise ValueError(f"{what}: {result} is not a finite number (a simulation takes no NaN or infinity)")
    return result


def whole(what: str, value: Any, least: int) -> int:
    """`value` as an int of at least `least`."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{what}: {value!r} is not a whole number")
    if int(value) < least:
        raise ValueError(f"{what}: {int(value)} is less than {least}")
    return int(value)


def parameter(name: str, value: Any) -> Any:
    """A parameter's value for a job or a study's fixed parameters: a number or a text."""
    return value if isinstance(value, str) else number(name, value)


def parameters(values: Mapping[str, Any] | None) -> dict[str, Any]:
    return {name: parameter(name, value) for name, value in (values or {}).items()}


def swept(name: str, spec: Any) -> Any:
    """A swept parameter: a list of values, or {"from", "to"[, "steps"]}."""
    if isinstance(spec, Mapping):
        unknown = set(spec) - {"from", "to", "steps"}
        if unknown or not {"from", "to"} <= set(spec):
            raise ValueError(f"{name}: give a list of values or {{'from': a, 'to': b, 'steps': n}}")
        out: dict[str, Any] = {"from": number(f"{name} from", spec["from"]),
                               "to": number(f"{name} to", spec["to"])}
        if "steps" in spec:
            out["steps"] = whole(f"{name} steps", spec["steps"], 1)
        return out
    if isinstance(spec, (str, bytes)) or not isinstance(spec, Sequence) and not hasattr(spec, "__iter__"):
        raise TypeError(f"{name}: give a list of values or {{'from': a, 'to': b, 'steps': n}}")
    values = [number(f"{name}[{i}]", v) for i, v in enumerate(spec)]
    if not values:
        raise ValueError(f"{name}: the list of values is empty")
    return values


def bound(name: str, spec: Any) -> dict[str, float]:
    """An optimised parameter: (min, max[, start]) or {"min", "max"[, "start"]}."""
    if isinstance(spec, Mapping):
        unknown = set(spec) - {"min", "max", "start"}
        if unknown or not {"min", "max"} <= set(spec):
            raise ValueError(f"{name}: give (min, max), (min, max, start) or {{'min': a, 'max': b}}")
        items = [(key, spec[key]) for key in ("min", "max", "start") if key in spec]
    else:
        if isinstance(spec, (str, bytes)) or len(spec) not in (2, 3):
            raise ValueError(f"{name}: give (min, max), (min, max, start) or {{'min': a, 'max': b}}")
        items = list(zip(("min", "max", "start"), spec))
    out = {key: number(f"{name} {key}", value) for key, value in items}
    if not out["min"] < out["max"]:
        raise ValueError(f"{name}: min {out['min']} is not below max {out['max']}")
    return out


def settings(start: Any, step: Any, stop: Any, log_samples: Any) -> dict[str, Any]:
    """Simulation settings for a request; absent ones are the model's own."""
    out: dict[str, Any] = {}
    if start is not None:
        out["start"] = number("start", start)
    if step is not None:
        out["step"] = number("step", step)
        if out["step"] <= 0:
            raise ValueError(f"step: {out['step']} is not a positive time step")
    if stop is not None:
        out["stop"] = number("stop", stop)
    if "start" in out and "stop" in out and not out["stop"] > out["start"]:
        raise ValueError(f"stop: {out['stop']} is not after start {out['start']}")
    if log_samples is not None:
        out["log_samples"] = whole("log_samples", log_samples, 1)
    return out
