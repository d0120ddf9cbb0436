"""Maximum efficiency of maxon DC motors from no-load and stall current, against the catalogue's printed
max. efficiency.

Source: maxon motor ag, "maxon DC motor: Key information": eta_max = (1 - sqrt(I0/I_A))^2. Printed values
(catalogue lines as transcribed in the reference projects, components/data/motors.toml):
RE 35 273762 (I0 17.2 mA, I_A 1.19 A, eta_max 77 %), the 6 V motor of project 003 Fig. 12 (52.9 mA, 4.07 A,
79 %), RE 13 1.8 V (53.8 mA, 1.62 A, 67 %).
"""

import pytest

from mechverify.components.motors import max_efficiency, motor
from mechverify.errors import InputError


@pytest.mark.parametrize(("name", "printed"), [("RE 35 273762", 0.77), ("maxon 6V 10.3 mNm", 0.79),
                                               ("maxon RE13", 0.67)])
def test_eta_max_against_printed(name, printed):
    """Code: 0.774, 0.785, 0.669 against printed 77 %, 79 %, 67 % (rounded to 1 % in the catalogue)."""
    m = motor(name)
    eta = max_efficiency(m.no_load_current.m_as("A"), m.stall_current.m_as("A"))
    assert eta == pytest.approx(printed, abs=0.006)
    assert eta == pytest.approx(m.max_efficiency, abs=0.006)


def test_eta_max_bad_input():
    with pytest.raises(InputError):
        max_efficiency(2.0, 1.0)
