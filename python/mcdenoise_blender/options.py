"""options.py: the denoise options shared by the Render Properties settings
and the sequence operator (mode, output), and what they mean as an mcdtool
command line for one frame file."""
import os

import bpy

#: mode -> the mcdtool chain it runs.
CHAINS = {
    "DENOISE": ["--denoise"],
    "DENOISE_BALANCED": ["--denoise:quality=balanced"],
    "DENOISE_FAST": ["--denoise:quality=fast"],
    "NLMEANS": ["--denoise:method=nlm"],
    "REPORT_CHAIN": ["--object-median", "7", "--gaussian", "3"],
}

#: The modes that run --denoise, which the light passes can join.
DENOISE_MODES = ("DENOISE", "DENOISE_BALANCED", "DENOISE_FAST", "NLMEANS")

MODE_ITEMS = (
    ("DENOISE", "Denoise",
     "mcdtool --denoise: Open Image Denoise's large networks (its high quality) on the Denoising Albedo and "
     "Normal passes, prefiltered as Blender's Accurate mode does; the OIDN this Blender lacks"),
    ("DENOISE_BALANCED", "Denoise (balanced)",
     "mcdtool --denoise:quality=balanced: Open Image Denoise's default-size networks, about twice as fast"),
    ("DENOISE_FAST", "Denoise (fast)", "mcdtool --denoise:quality=fast: Open Image Denoise's small networks"),
    ("NLMEANS", "Non-local means",
     "mcdtool --denoise:method=nlm: the network-free operator, non-local means guided by the Denoising Data "
     "passes"),
    ("REPORT_CHAIN", "Report's chain", "mcdtool --object-median 7 --gaussian 3, guided by the Object Index pass"),
)

OUTPUT_ITEMS = (
    ("IN_PLACE", "In place", "Replace each frame file with its denoised version (written beside it, then renamed)"),
    ("PATTERN", "Sibling path", "Write the denoised frame to a path made from the frame's own (the raw frame is kept)"),
)


def mode_property(update=None):
    """The Mode property (`update` is called when it changes)."""
    return bpy.props.EnumProperty(name="Mode", items=MODE_ITEMS, default="DENOISE", update=update)


class DenoiseOptions:
    """Mix-in: the properties both the scene settings and the operator have."""
    mode: mode_property()
    output: bpy.props.EnumProperty(name="Output", items=OUTPUT_ITEMS, default="IN_PLACE")
    light_passes: bpy.props.BoolProperty(
        name="Denoise light passes", default=False,
        description="With a Denoise mode: also denoise the Diffuse, Glossy, Transmission, Volume, Emission and "
                    "Environment light passes with the beauty (mcdtool --aovs auto), so the compositor's "
                    "rebuild of them is the denoised beauty (on the non-local means operator for now: the network has no "
                    "light-pass mode yet); turns those passes on")
    pattern: bpy.props.StringProperty(
        name="Path", default="{name}_denoised.exr",
        description="Denoised file, relative to the frame's folder: {name} is the frame file's name without "
                    "its extension (e.g. denoised/{name}.exr); absolute and // paths are allowed")


def output_path(frame_file, output, pattern):
    """Where the denoised version of `frame_file` goes."""
    if output == "IN_PLACE":
        return frame_file
    name = os.path.splitext(os.path.basename(frame_file))[0]
    path = bpy.path.abspath(pattern.replace("{name}", name))
    return os.path.normpath(os.path.join(os.path.dirname(frame_file), path))


def command_line(frame_file, mode, output, pattern, light_passes=False):
    """mcdtool's command line (without the program name) for one frame file;
    in place is mcdtool's --force (a temp file beside it, renamed over it);
    `light_passes` with a mode that runs --denoise adds --aovs auto."""
    target = output_path(frame_file, output, pattern)
    aovs = ["--aovs", "auto"] if light_passes and mode in DENOISE_MODES else []
    args = [frame_file] + CHAINS[mode] + aovs + ["-o", target]
    return args + ["--force"] if output == "IN_PLACE" else args
