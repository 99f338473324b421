"""mcdenoise for Blender: denoises every frame Blender writes as OpenEXR
MultiLayer with mcdtool's own per-frame code (through the compiled mcdenoise
Python module), and an Image-editor operator for existing EXR sequences.

Debian's Blender is built without OpenImageDenoise, so Cycles offers no
denoiser there; this add-on is one. Install the zip that the CMake target
`blender_addon` builds (Edit > Preferences > Add-ons > Install); the compiled
module is found as docs/blender.md describes (add-on preference, the build
directory recorded in the zip, then sys.path).
"""
bl_info = {
    "name": "mcdenoise",
    "author": "mcdenoise",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Render > mcdenoise; Image editor > Image > Denoise EXR Sequence",
    "description": "Denoise Cycles renders with mcdenoise after each frame is written",
    "category": "Render",
}

from . import handlers, operator, panel, preferences, reports, settings  # noqa: E402

_MODULES = (preferences, reports, settings, panel, operator, handlers)


def register():
    for module in _MODULES:
        module.register()


def unregister():
    for module in reversed(_MODULES):
        module.unregister()
