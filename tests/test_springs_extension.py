"""ExtensionSpring accessors (Shigley 10th ed. Sec. 10-11)."""


def test_hook_side_radius_is_none_when_not_given():
    """r2 is optional: without it the accessor says None (it returned nan mm: the NaN marker leaked out)."""
    from mechverify.components.springs import ExtensionSpring

    s = ExtensionSpring(d="1.5 mm", Nb=20, OD="12 mm", r2=None)
    assert s.hook_side_radius is None
    assert ExtensionSpring(d="1.5 mm", Nb=20, OD="12 mm", r2="2 mm").hook_side_radius.m_as("mm") == 2.0


def test_moduli_and_wire_strength_one_rule_for_the_three_springs():
    """G, E given on a spring or taken from its material, positive; Sut given or the material's wire strength at d
    (Shigley Table 10-4): one rule (HelicalSpring._wire_si) for compression, extension and torsion springs. A negative
    modulus was accepted by the extension and torsion springs."""
    import pytest

    from mechverify.components.springs import CompressionSpring, ExtensionSpring, TorsionSpring
    from mechverify.errors import InputError

    geo = dict(d="1.5 mm", D="12 mm")
    ext, tor = ExtensionSpring(**geo, Nb=20), TorsionSpring(**geo, Nb=6)
    comp = CompressionSpring(**geo, Na=8, L0="60 mm")
    assert ext.si["Sut"] == tor.si["Sut"] == comp.si["Sut"]  # A228 at 1.5 mm, from the same table
    assert ExtensionSpring(**geo, Nb=20, Sut="1.5 GPa").si["Sut"] == 1.5e9
    assert ext.si["G"] == comp.si["G"] and tor.si["E"] == comp.si["E"]
    for make in (lambda: ExtensionSpring(**geo, Nb=20, G="-80 GPa"), lambda: TorsionSpring(**geo, Nb=6, E="0 GPa"),
                 lambda: CompressionSpring(**geo, Na=8, L0="60 mm", E="-1 GPa")):
        with pytest.raises(InputError, match="must be positive"):
            make()
