"""Result files: HDF5 tilt and shake files (inputs, settings, versions and time histories)."""
