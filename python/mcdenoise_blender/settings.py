"""settings.py: the scene's mcdenoise settings (scene.mcdenoise, shown in
Render Properties) and `prepare_scene`, which makes the scene write what the
chain needs: the guide passes on, Cycles' own denoiser off, and a report when
the output format cannot carry the passes."""
import bpy

from . import options, reports

#: The one file format that carries every pass of a frame.
MULTILAYER = "OPEN_EXR_MULTILAYER"


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


def register():
    bpy.utils.register_class(McdenoiseSettings)
    bpy.types.Scene.mcdenoise = bpy.props.PointerProperty(type=McdenoiseSettings)


def unregister():
    del bpy.types.Scene.mcdenoise
    bpy.utils.unregister_class(McdenoiseSettings)
