"""Both engines against limit analysis (``run``), the figure (``figure``), the command
``compare-engines``."""
