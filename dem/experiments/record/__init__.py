"""Recorded accelerograms: the DEM runs of records for an assessment (``run``), the command
``record`` and the campaign step ``record``."""
