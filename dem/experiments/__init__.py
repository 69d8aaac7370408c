"""Virtual experiments built on ``simulate``: the tilt test, shake-table runs, shake thresholds and
DEM failure domains, the friction map, and the engine comparison."""
