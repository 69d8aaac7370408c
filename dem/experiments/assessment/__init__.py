"""The code-based assessment of a monument: the figure (``figure``), the command ``assess`` and the
campaign step ``assess``."""
