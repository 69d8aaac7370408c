"""The virtual test campaign: the runner and its list of steps (each step lives with its experiment),
the catalogue and analytic steps, the time estimate, the HTML report and the ``campaign`` command."""
