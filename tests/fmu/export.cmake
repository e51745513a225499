# Export side of the FMU tests.
