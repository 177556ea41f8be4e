"""The command line interface ``epicyclic`` (typer)."""
