"""ExtensionSpring accessors (Shigley 10th ed. Sec. 10-11)."""


def test_hook_side_radius_is_none_when_not_given():
    """r2 is optional: without it the accessor says None (it returned nan mm: the NaN marker leaked out)."""
    from mechverify.components.springs import ExtensionSpring

    s = ExtensionSpring(d="1.5 mm", Nb=20, OD="12 mm", r2=None)
    assert s.hook_side_radius is None
    assert ExtensionSpring(d="1.5 mm", Nb=20, OD="12 mm", r2="2 mm").hook_side_radius.m_as("mm") == 2.0
