"""Code-based assessment: the kinematic analysis (``kinematic``), FRP strips (``frp``), the checks
of a mechanism against a site (``assessment``) and fragility statistics (``fragility``)."""
