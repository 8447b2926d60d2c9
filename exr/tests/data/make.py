"""Writes the hand-made spectral OpenEXR files the reader is tested on, with
OpenImageIO (another writer than speclab-exr): 4 x 3 pixels, values
`pixel + channel / 8` (pixel = y * 4 + x, channel in order of wavelength), so a
test can tell every value apart. Run: python make.py (OpenImageIO >= 2.5)."""
import numpy as np
import OpenImageIO as oiio

W, H = 4, 3


def write(name, channels, attributes, values=None):
    n = len(channels)
    spec = oiio.ImageSpec(W, H, n, oiio.FLOAT)
    spec.channelnames = channels
    spec.attribute("compression", "zip")
    for key, value in attributes.items():
        spec.attribute(key, value)
    if values is None:
        values = np.zeros((H, W, n), dtype=np.float32)
        for i, c in enumerate(channels):
            values[:, :, i] = np.arange(W * H, dtype=np.float32).reshape(H, W) + 0.125 * i
    out = oiio.ImageOutput.create(name)
    out.open(name, spec)
    out.write_image(values)
    out.close()


EMISSIVE = {"spectralLayoutVersion": "1.0", "emissiveUnits": "W.m^-2.sr^-1"}
# pbrt-v4's SpectralFilm names: comma decimals, RGB preview channels first.
pbrt = ["R", "G", "B", "S0.374,688nm", "S0.400nm", "S0.425,312nm", "S0.1000nm"]
write("pbrt_emissive.exr", pbrt, EMISSIVE)
# Reflective, wavelengths in micrometres and metres.
write("reflective_units.exr", ["T.0,45um", "T.5,5e-7m", "T.650nm"], {"spectralLayoutVersion": "1.0"})
# Polarised: S0 to S3 at the same wavelengths.
stokes = [f"S{k}.{l}nm" for k in range(4) for l in (450, 550, 650)]
write("polarised.exr", stokes, dict(EMISSIVE, polarisationHandedness="right"))
# Broken files, one fault each.
write("bad_name.exr", ["S0.450nm", "S0.550.5nm"], EMISSIVE)
write("no_version.exr", ["S0.450nm", "S0.550nm"], {"emissiveUnits": "W.m^-2.sr^-1"})
write("no_units.exr", ["S0.450nm", "S0.550nm"], {"spectralLayoutVersion": "1.0"})
write("version_2.exr", ["S0.450nm", "S0.550nm"], {"spectralLayoutVersion": "2.0", "emissiveUnits": "W.m^-2.sr^-1"})
write("disagree.exr", ["S0.450nm", "S0.550nm", "S1.450nm", "S1.560nm"], dict(EMISSIVE, polarisationHandedness="right"))
write("rgb_only.exr", ["R", "G", "B"], {})
write("stokes_only.exr", ["S1.450nm", "S1.550nm"], dict(EMISSIVE, polarisationHandedness="right"))
write("duplicate.exr", ["S0.450nm", "S0.4,5e2nm", "S0.550nm"], EMISSIVE)
write("polarised_left.exr", stokes, dict(EMISSIVE, polarisationHandedness="left"))
write("bad_handedness.exr", stokes, dict(EMISSIVE, polarisationHandedness="up"))
