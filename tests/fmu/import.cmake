# Import side of the FMU tests.
