import os

# figures are written to files in tests; never open a window
os.environ.setdefault("MPLBACKEND", "Agg")
