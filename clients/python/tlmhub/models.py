"""A model's contents from scripts: its parameters and loggable variables, and structural
editing (add, remove, rename and connect components, set parameters, save) over the
server's edit protocol on the WebSocket (protocol/README.md, "WebSocket")."""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Sequence, Union

from . import _values, _websocket
from .errors import ApiError, error_for

if TYPE_CHECKING:
    from .client import Client, Model


@dataclass(frozen=True)
class Parameter:
    """A parameter of a model, as the server lists it.

    `name` is the path runs, studies and `ModelEditor.set` take: `GainP.k` (a component's
    `k#Value` is named without `#Value`), `Mass.m`, a start value `Tank_C.P1#Flow`, a system
    parameter of the root `gain`, inside a subsystem `Sub$Gain.k` or `Sub.gain` (Sub's own).
    `value` is the text as stored (a number or an expression); `number` its float, or None
    when it is an expression. `component` is the owner's path (`GainP`, `Sub$Gain`; "" for
    the root system) and `key` the owner's own name for it (`k#Value`). The server keeps no
    bounds for a model's parameters (only an assignment's locks have them)."""
    name: str
    value: str
    unit: str
    description: str
    type: str
    component: str
    key: str

    @property
    def number(self) -> float | None:
        try:
            return float(self.value)
        except ValueError:
            return None


@dataclass(frozen=True)
class Variable:
    """A variable a run logs: `name` is the result's column (`Mass#P2#Position`, inside a
    subsystem `Sub$Comp#Port#Var`), `unit` as the server gives it ("" for most signals)."""
    name: str
    unit: str

    @property
    def component(self) -> str:
        return self.name.split("#")[0]

    @property
    def port(self) -> str:
        return self.name.split("#")[1]

    @property
    def variable(self) -> str:
        return self.name.split("#")[2]


def parameters_of(model: dict[str, Any]) -> dict[str, Parameter]:
    """The parameters of a model structure (`ModelDetail.model`, `model.get`), by name, in
    the model's order: the root's system parameters, then each component's."""
    out: dict[str, Parameter] = {}
    _collect(model["system"], "", "", out)
    return out


def _collect(system: dict[str, Any], prefix: str, owner: str, out: dict[str, Parameter]) -> None:
    # `owner`: how a system parameter of this system is named ("" at the root, "Sub." inside).
    for p in system.get("parameters", []):
        _add(out, owner + p["name"], owner[:-1], p)
    for component in system.get("components", []):
        path = prefix + component["name"]
        for p in component.get("parameters", []):
            key = p["name"]
            short = key[: -len("#Value")] if key.endswith("#Value") else key
            _add(out, f"{path}.{short}", path, p)
        if "system" in component:
            _collect(component["system"], path + "$", path + ".", out)


def _add(out: dict[str, Parameter], name: str, component: str, p: dict[str, Any]) -> None:
    if name not in out:
        out[name] = Parameter(name, str(p.get("value", "")), str(p.get("unit", "")),
                              str(p.get("description", "")), str(p.get("type", "")), component,
                              str(p["name"]))


PortName = Union[str, Sequence[str]]


def port_ref(port: PortName) -> dict[str, str]:
    """`"Comp.port"` (or `("Comp", "port")`) as the protocol's PortRef; a system port is its
    own name alone (`"P1"`: component and port both P1)."""
    if isinstance(port, str):
        component, dot, name = port.rpartition(".")
        if not dot:
            component = name = port
    else:
        component, name = port
    if not component or not name:
        raise ValueError(f"name a port as 'Component.port', not {port!r}")
    return {"component": component, "port": name}


def _owner(path: str) -> tuple[list[str], str]:
    """`Sub$Comp` as the system path `["Sub"]` and the component `Comp`."""
    parts = path.split("$")
    return parts[:-1], parts[-1]


class ModelEditor:
    """A model opened for editing on its own WebSocket (`client.models.edit(id)`); changes
    stay in the server's memory until `save()`, and closing without saving drops them.

    Components are named by their name; inside a subsystem give `system=["Sub"]`, or name
    it by its path `Sub$Comp` as parameters and results do. A refused edit raises the client's
    ApiError kinds with the server's code and message (status 0: a WebSocket reply):
    Refused (`illegal_connection`, `invalid_parameter`, `unknown_component_type`, ...),
    NotFound (`not_found`), Unauthorized, LimitExceeded."""

    def __init__(self, client: "Client", model_id: int):
        if not _websocket.available():
            raise ImportError("model editing " + _websocket.WEBSOCKET_MISSING)
        self._client = client
        self._socket = _websocket.Socket(client._transport)
        try:
            opened = self._call("model.open", model_id=int(model_id))
        except BaseException:
            self._socket.close()
            raise
        self.model_id = int(opened["model_id"])
        self.writable = bool(opened.get("writable"))

    def __enter__(self) -> "ModelEditor":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Ends the editing socket; what was not saved is dropped."""
        self._socket.close()

    def _call(self, type_: str, **fields: Any) -> dict[str, Any]:
        try:
            reply = self._socket.call(type_, **fields)
        except ApiError as error:
            if type(error) is not ApiError or error.code in ("closed", "bad_reply", "websocket_error"):
                raise
            # The socket's errors carry no HTTP status: their kind follows the code.
            raise _typed(error.code, error.message) from None
        # Events of nothing this editor subscribed to are of no use to it.
        self._socket.pending.clear()
        return reply

    def model(self) -> dict[str, Any]:
        """The open model's structure as it is now (`Model`: name, system, ...)."""
        return self._call("model.get")["model"]

    def parameters(self) -> dict[str, Parameter]:
        """The open model's parameters as they are now, unsaved changes included."""
        return parameters_of(self.model())

    def add(self, type: str, name: str | None = None, x: float = 0, y: float = 0,
            angle: float = 0, flipped: bool = False, system: Sequence[str] | None = None) -> str:
        """Adds a component of a catalogue type (`client.components()`); returns its name,
        which the server makes unique (the type's name when `name` is None)."""
        fields: dict[str, Any] = {"component_type": type, "pose": _pose(x, y, angle, flipped)}
        if name is not None:
            fields["name"] = name
        if system:
            fields["system"] = list(system)
        return str(self._call("component.add", **fields)["component"]["name"])

    def remove(self, name: str, system: Sequence[str] | None = None) -> None:
        """Removes a component and its connections."""
        path, component = self._where(name, system)
        self._call("component.remove", name=component, **path)

    def rename(self, name: str, new_name: str, system: Sequence[str] | None = None) -> str:
        """Renames a component (its connections follow); returns the name it got: other
        characters than A-Z a-z 0-9 _ become `_`, a taken name gets a suffix."""
        path, component = self._where(name, system)
        return str(self._call("component.rename", name=component, new_name=new_name, **path)["name"])

    def move(self, name: str, x: float, y: float, angle: float = 0, flipped: bool = False,
             system: Sequence[str] | None = None) -> None:
        """Changes only where the editor draws a component."""
        path, component = self._where(name, system)
        self._call("component.move", name=component, pose=_pose(x, y, angle, flipped), **path)

    def connect(self, a: PortName, b: PortName, system: Sequence[str] | None = None) -> None:
        """Connects two ports, each `"Component.port"` (`"Mass.P2"`); a system port is named
        by itself (`"P1"`). A connection the core refuses raises Refused with code
        `illegal_connection` and the core's reason."""
        self._call("connect", **{"from": port_ref(a), "to": port_ref(b)}, **_system(system))

    def disconnect(self, a: PortName, b: PortName, system: Sequence[str] | None = None) -> None:
        """Removes the connection of two ports (Refused, `illegal_connection`, when they are
        not connected)."""
        self._call("disconnect", **{"from": port_ref(a), "to": port_ref(b)}, **_system(system))

    def replace(self, name: str, type: str, keep_parameters: bool = True,
                system: Sequence[str] | None = None) -> str:
        """Replaces a component by one of another type under the same name and pose,
        connected as it was (each of its connections to a port the new type has, else
        Refused `illegal_connection` or NotFound); `keep_parameters` carries over the values
        of the parameters both types have. Returns the new component's name."""
        path, component = self._where(name, system)
        structure = self.model()["system"]
        for sub in path.get("system", []):
            structure = next(c["system"] for c in structure["components"] if c["name"] == sub)
        old = next((c for c in structure["components"] if c["name"] == component), None)
        if old is None:
            raise _typed("not_found", f"no component named {component!r}")
        ends = [(c["from"], c["to"]) for c in structure["connections"]
                if component in (c["from"]["component"], c["to"]["component"])]
        self._call("component.remove", name=component, **path)
        pose = old.get("pose", {})
        added = self._call("component.add", component_type=type, name=component,
                           pose=_pose(pose.get("x", 0), pose.get("y", 0), pose.get("angle", 0),
                                      pose.get("flipped", False)), **path)["component"]
        new_name = str(added["name"])

        def renamed(end: dict[str, str]) -> dict[str, str]:
            return {**end, "component": new_name} if end["component"] == component else end

        for a, b in ends:
            self._call("connect", **{"from": renamed(a), "to": renamed(b)}, **path)
        if keep_parameters:
            defaults = {p["name"]: str(p["value"]) for p in added["parameters"]}
            for p in old.get("parameters", []):
                if p["name"] in defaults and defaults[p["name"]] != str(p["value"]):
                    self._call("parameter.set", component=new_name, parameter=p["name"],
                               value=str(p["value"]), **path)
        return new_name

    def get(self, name: str) -> Parameter:
        """One parameter as it is now, by the name `parameters()` gives it."""
        found = self.parameters().get(name)
        if found is None:
            raise _typed("not_found", f"the model has no parameter {name!r}")
        return found

    def set(self, name: str, value: Any) -> Parameter:
        """Sets a parameter by its name (`GainP.k`, `Mass.m`, `Sub$Gain.k`, a system
        parameter `gain` or `Sub.gain`) to a number or an expression; returns it as the server
        now has it. A value that does not evaluate raises Refused, `invalid_parameter`, and
        the old value stays."""
        value = _value(name, value)
        owner, dot, key = name.partition(".")
        if not dot:
            existing = parameters_of(self.model()).get(name)
            if existing is None or existing.component != "":
                raise _typed("not_found", f"the model has no system parameter {name!r} "
                             "(set_system_parameter creates one)")
            reply = self._call("sysparam.set", name=name, value=value)
            return _parameter(name, "", reply["parameter"])
        system, component = _owner(owner)
        fields = {"component": component, "value": value, **_system(system)}
        try:
            reply = self._call("parameter.set", parameter=key, **fields)
        except ApiError as first:
            # As runs name them: `Comp.k` is the input variable's start value `k#Value`.
            if first.code != "not_found" or key.endswith("#Value"):
                raise
            try:
                reply = self._call("parameter.set", parameter=key + "#Value", **fields)
            except ApiError as second:
                raise (first if second.code == "not_found" else second) from None
        return _parameter(name, owner, reply["parameter"])

    def set_system_parameter(self, name: str, value: Any, unit: str | None = None,
                             description: str | None = None, type: str | None = None,
                             system: Sequence[str] | None = None) -> Parameter:
        """Creates or changes a system parameter (of the root, or of the subsystem at
        `system`); unit, description and type keep their old values when None."""
        fields: dict[str, Any] = {"name": name, "value": _value(name, value), **_system(system)}
        for key, given in (("unit", unit), ("description", description), ("param_type", type)):
            if given is not None:
                fields[key] = given
        reply = self._call("sysparam.set", **fields)
        owner = "$".join(system or [])
        return _parameter(f"{owner}.{name}" if owner else name, owner, reply["parameter"])

    def settings(self, start: float | None = None, step: float | None = None,
                 stop: float | None = None, log_samples: int | None = None) -> dict[str, Any]:
        """Changes the model's own simulation settings (saved with it); returns all four."""
        return self._call("model.settings", **_values.settings(start, step, stop, log_samples))["simulation"]

    def save(self, as_copy: bool = False, name: str | None = None) -> "Model":
        """Stores the open model. A model the user may not change (an example), or
        `as_copy=True`, is saved as a new model of the user's (named `name`), which stays
        open here; `model_id` is then the new one's."""
        from .client import Model
        fields: dict[str, Any] = {}
        if as_copy:
            fields["as_copy"] = True
        if name is not None:
            fields["name"] = name
        saved = self._call("model.save", **fields)
        self.model_id = int(saved["model_id"])
        if saved.get("copied"):
            self.writable = True
        return Model(self.model_id, str(saved.get("name", "")), dict(saved), _client=self._client)

    def _where(self, name: str, system: Sequence[str] | None) -> tuple[dict[str, Any], str]:
        path, component = _owner(name)
        return _system(list(system or []) + path), component

    def __repr__(self) -> str:
        return f"<ModelEditor of model {self.model_id}>"


def _value(name: str, value: Any) -> Any:
    """A number or an expression; a bool as the text a bool parameter holds."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return _values.parameter(name, value)


def _system(system: Sequence[str] | None) -> dict[str, Any]:
    return {"system": list(system)} if system else {}


def _pose(x: float, y: float, angle: float, flipped: bool) -> dict[str, Any]:
    return {"x": _values.number("x", x), "y": _values.number("y", y),
            "angle": _values.number("angle", angle), "flipped": bool(flipped)}


def _parameter(name: str, component: str, p: dict[str, Any]) -> Parameter:
    return Parameter(name, str(p.get("value", "")), str(p.get("unit", "")),
                     str(p.get("description", "")), str(p.get("type", "")), component, str(p["name"]))


# The WebSocket's error codes by the HTTP status REST gives the same refusal, so an edit
# raises the kind a REST call would (errors.error_for); the status itself stays 0.
_KIND_STATUS = {"unauthorized": 401, "not_found": 404, "limit_exceeded": 422, "rate_limited": 429,
                "internal": 500, "storage_full": 507, "busy": 503, "unavailable": 503}


def _typed(code: str, message: str) -> ApiError:
    kind = type(error_for(_KIND_STATUS.get(code, 400), code, message))
    return kind(0, code, message)
