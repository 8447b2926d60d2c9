"""Writes spectral OpenEXR files as colour-science 0.4.7's
`write_spectral_image_Fichet2021` does with its default specification (no
`spectralLayoutVersion`, and for emissive images no `emissiveUnits`): the
files other writers make that the reader must read, reporting what they
lack. 4 x 3 pixels, values `pixel + channel / 8` as in make.py (exact in
f16). Run: python make_colour.py (colour-science 0.4.7, OpenImageIO)."""
import numpy as np
from colour.io import Specification_Fichet2021, write_spectral_image_Fichet2021

W, H = 4, 3
WAVELENGTHS = np.array([400.0, 450.0, 500.5, 550.0, 600.0, 650.0, 700.0, 750.0])


def values():
    v = np.zeros((H, W, len(WAVELENGTHS)))
    for i in range(len(WAVELENGTHS)):
        v[:, :, i] = np.arange(W * H).reshape(H, W) + 0.125 * i
    return v


for emissive, component in [(True, "S0"), (False, "T")]:
    for depth in ("float32", "float16"):
        name = f"colour_{'emissive' if emissive else 'reflective'}_{depth[5:]}.exr"
        specification = Specification_Fichet2021(is_emissive=emissive)
        write_spectral_image_Fichet2021({component: (WAVELENGTHS, values())}, name, depth, specification)
