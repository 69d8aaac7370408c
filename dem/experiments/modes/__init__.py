"""Natural frequencies on compliant joints: DEM free vibration (``run``) beside the analytic modes,
the figure (``figure``), the command ``modes`` and the campaign step ``modes``."""
