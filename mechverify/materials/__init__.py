"""Material database: ``materials.get("PLA")``, ``materials.names()``, derived materials with ``.with_()``."""

from mechverify.materials.database import MaterialLibrary, default_library, get, load_toml, material_from_dict, names
from mechverify.materials.material import Material, SNCurve, WireStrength

__all__ = ["Material", "SNCurve", "WireStrength", "MaterialLibrary", "get", "names", "load_toml",
           "material_from_dict", "default_library"]
