"""The simulator core: the model handed to an engine, loads, settings, ``simulate``, collapse and
failure-mode detection, provenance, and the engines (PyBullet, MuJoCo) behind one interface."""
