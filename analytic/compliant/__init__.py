"""Compliant joints: natural frequencies (``modes``) and the tilt by statics (``elastic_tilt``)."""
