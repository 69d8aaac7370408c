"""The rest state of an arch: its blocks left under gravity on their base (``run``), the command
``settle`` and the optional campaign step ``settle``; declared in ``experiment``."""
