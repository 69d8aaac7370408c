"""Rocking dynamics: one-degree-of-freedom mechanisms (``mechanism``), the rocking block
(``rocking_block``), the four-bar and two-bar linkages (``linkage``), impact (``impact``), time
histories (``dynamics``), failure domains (``domain``) and their figures (``figures``)."""
