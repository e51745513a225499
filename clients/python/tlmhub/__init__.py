"""Python client for tlmhub: run simulations, sweeps, sensitivity studies and optimisations
on a tlmhub server from scripts.

    import tlmhub
    client = tlmhub.Client("https://tlmhub.example.org", token)
    result = client.run("Position Servo.hmf", parameters={"GainP.k": 0.03})
    print(result["Mass#P2#Position"][-1])

REST uses only the standard library; `client.stream`, live study progress and model
editing (`client.models.edit`) need websocket-client (`tlmhub[stream]`), NumPy columns need
NumPy (`tlmhub[numpy]`), `to_pandas()` needs pandas (`tlmhub[pandas]`)."""
from .client import Client, Job, Model
from .errors import (ApiError, ConnectionFailed, LimitExceeded, NotFound, Refused, SimulationFailed,
                     Unauthorized)
from .models import ModelEditor, Parameter, Variable
from .results import Grid, Result, Table
from .studies import Study

__all__ = ["ApiError", "Client", "ConnectionFailed", "Grid", "Job", "LimitExceeded", "Model", "ModelEditor",
           "NotFound", "Parameter", "Refused", "Result",
           "SimulationFailed", "Study", "Table", "Unauthorized", "Variable"]
