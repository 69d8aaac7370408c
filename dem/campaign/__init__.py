"""The virtual test campaign: a runner, one module per step (catalogue, analytic, tilt, map, shake,
record), the time estimate and the HTML report."""
