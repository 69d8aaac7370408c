"""Studies: the sweep engine (cases on all cores or a Dask cluster, one HDF5 study file, resume)."""
