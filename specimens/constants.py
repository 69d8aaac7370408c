"""Physical constants and reference values shared by every layer (SI units)."""

G = 9.81  # m/s^2, standard gravity used throughout archdem
REFERENCE_MU_JOINT = 0.577  # block-block Coulomb friction of the specimens, tan 30 deg (docs/physics/geometry.md#9-the-specimen-catalogue)
REFERENCE_MU_BASE = 1.0  # last block-base Coulomb friction, tan 45 deg
NO_SLIDING_MU = 10.0  # a friction "high enough to prevent sliding": the no-sliding validation (docs/validation.md#1-how-to-reproduce)
DRAWN_DENSITY = 2000.0  # kg/m^3, a drawing's unless stated: stone or brick masonry, not the specimens' aerated concrete (docs/physics/geometry.md#16-assemblies-from-drawings)
#: Lengths archdem takes [m], typed (an arch option) or drawn (a drawing's extent, a block's depth): a typo such as
#: --Rc 1e30, or a drawing read in the wrong units, is refused, not simulated.
MIN_LENGTH_M, MAX_LENGTH_M = 1e-3, 1000.0
