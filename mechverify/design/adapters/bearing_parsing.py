"""The lubricant and duty-cycle keys shared by the rolling-bearing types (``ball_bearing``, ``rolling_bearing``).

Declares no type: :data:`LUBRICANT_FIELDS` is spliced into each type's fields, so the two types accept the same
keys with the same meaning (ISO 281 Sec. 9 modified life: the oil's viscosity by ISO VG and viscosity index or
at 40/100 degC, the operating temperature, the contamination level; the duty cycle of time shares).
"""

from __future__ import annotations

from mechverify.components.bearings import CONTAMINATION_LEVELS
from mechverify.design.spec import Field

#: The lubricant and duty-cycle keys of every rolling-bearing type.
LUBRICANT_FIELDS = (
    Field("viscosity_40", "str", "lubricant viscosity at 40 degC, e.g. '68 mm^2/s'"),
    Field("iso_vg", "int", "ISO 3448 viscosity grade (its 40 degC viscosity), instead of viscosity_40"),
    Field("viscosity_100", "str", "lubricant viscosity at 100 degC (oil datasheet), with viscosity_40 or iso_vg"),
    Field("viscosity_index", "float", "viscosity index (ASTM D2270), instead of viscosity_100: iso_vg = 68 with "
                                      "viscosity_index = 95 gives nu(T)"),
    Field("operating_temperature", "str", "bearing operating temperature, e.g. '70 degC' (-20..150 degC)"),
    Field("contamination", "choice", "ISO 281 Table 13 contamination level (its lower e_C is used)",
          default="normal_cleanliness", choices=tuple(CONTAMINATION_LEVELS)),
    Field("contamination_factor", "float", "e_C (0..1), instead of the contamination level"),
    Field("duty_cycle", "table", "load case = time share, e.g. { run = 0.7, start = 0.3 }: the life is taken "
                                 "over the cycle, P = (sum P_i^p n_i t_i / sum n_i t_i)^(1/p), p = 3 for ball and "
                                 "10/3 for roller bearings"),
)
