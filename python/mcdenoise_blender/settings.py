"""settings.py: the scene's mcdenoise settings (scene.mcdenoise, shown in
Render Properties) and `prepare_scene`, which makes the scene write what the
chain needs: the guide passes on, Cycles' own denoiser off, and a report when
the output format cannot carry the passes."""
import bpy

from . import options, reports

#: The one file format that carries every pass of a frame.
MULTILAYER = "OPEN_EXR_MULTILAYER"


#: The view-layer properties of the light passes --aovs auto denoises, and
#: of the colour passes their rebuild needs.
LIGHT_PASSES = ("use_pass_diffuse_direct", "use_pass_diffuse_indirect", "use_pass_diffuse_color",
                "use_pass_glossy_direct", "use_pass_glossy_indirect", "use_pass_glossy_color",
                "use_pass_transmission_direct", "use_pass_transmission_indirect", "use_pass_transmission_color",
                "use_pass_emit", "use_pass_environment")
#: Cycles' own (layer.cycles) light passes.
CYCLES_LIGHT_PASSES = ("use_pass_volume_direct", "use_pass_volume_indirect")


def _turn_on_light_passes(layer):
    """Turns on every light and colour pass of `layer` (saying so once)."""
    cycles_layer = getattr(layer, "cycles", None)
    targets = [(layer, name) for name in LIGHT_PASSES if hasattr(layer, name)]
    targets += [(cycles_layer, name) for name in CYCLES_LIGHT_PASSES if hasattr(cycles_layer, name)]
    changed = False
    for owner, name in targets:
        if not getattr(owner, name):
            setattr(owner, name, True)
            changed = True
    if changed:
        reports.report("INFO", f"turned on the light passes of view layer '{layer.name}'")


def prepare_scene(scene):
    """Turns on the passes the chain reads and Cycles' denoiser off (saying
    what it changed); returns False, with a warning, when the frames cannot
    be denoised as set (the output is not OpenEXR MultiLayer)."""
    settings = scene.mcdenoise
    if scene.render.engine == "CYCLES" and scene.cycles.use_denoising:
        scene.cycles.use_denoising = False
        reports.report("INFO", "turned Cycles' own denoiser off (this Blender may lack OpenImageDenoise); "
                               "mcdenoise denoises the written frames")
    for layer in scene.view_layers:
        if not layer.use:
            continue
        cycles_layer = getattr(layer, "cycles", None)
        if cycles_layer is not None and not cycles_layer.denoising_store_passes:
            cycles_layer.denoising_store_passes = True
            reports.report("INFO", f"turned on the Denoising Data passes of view layer '{layer.name}'")
        if settings.mode == "REPORT_CHAIN" and not layer.use_pass_object_index:
            layer.use_pass_object_index = True
            reports.report("INFO", f"turned on the Object Index pass of view layer '{layer.name}'")
        if settings.mode in options.DENOISE_MODES and settings.light_passes:
            _turn_on_light_passes(layer)
    if scene.render.engine != "CYCLES":
        reports.report("WARNING", f"the render engine is {scene.render.engine}: the Denoising Data guide "
                                  "passes are Cycles'; frames are denoised with the passes there are")
    file_format = scene.render.image_settings.file_format
    if file_format != MULTILAYER:
        reports.report("WARNING", f"the output format {file_format} cannot carry the passes mcdenoise needs: "
                                  "set Output Properties > File Format to OpenEXR MultiLayer; "
                                  "frames are written but not denoised")
        return False
    return True


def _on_change(settings, context):
    if settings.enabled:
        prepare_scene(settings.id_data)


class McdenoiseSettings(options.DenoiseOptions, bpy.types.PropertyGroup):
    enabled: bpy.props.BoolProperty(
        name="Denoise written frames", default=False, update=_on_change,
        description="Denoise every frame Blender writes as OpenEXR MultiLayer, after it is written")
    mode: options.mode_property(update=_on_change)  # the passes it needs change with it
    light_passes: bpy.props.BoolProperty(
        name="Denoise light passes", default=False, update=_on_change,
        description="With a Denoise mode: also denoise the Diffuse, Glossy, Transmission, Volume, Emission and "
                    "Environment light passes with the beauty (mcdtool --aovs auto), so the compositor's "
                    "rebuild of them is the denoised beauty (on the non-local means operator for now: the network has no "
                    "light-pass mode yet); turns those passes on")


def register():
    bpy.utils.register_class(McdenoiseSettings)
    bpy.types.Scene.mcdenoise = bpy.props.PointerProperty(type=McdenoiseSettings)


def unregister():
    del bpy.types.Scene.mcdenoise
    bpy.utils.unregister_class(McdenoiseSettings)
