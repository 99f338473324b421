"""panel.py: the "mcdenoise" panel of Render Properties: enable, mode and
output, with the output format and the compiled module's state."""
import bpy

from . import locate, preferences, settings
from .options import DENOISE_MODES


class RENDER_PT_mcdenoise(bpy.types.Panel):
    bl_label = "mcdenoise"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "render"

    def draw_header(self, context):
        self.layout.prop(context.scene.mcdenoise, "enabled", text="")

    def draw(self, context):
        options = context.scene.mcdenoise
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        column = layout.column()
        column.active = options.enabled
        column.prop(options, "mode")
        if options.mode in DENOISE_MODES:
            column.prop(options, "light_passes")
        column.prop(options, "output")
        if options.output == "PATTERN":
            column.prop(options, "pattern")
        file_format = context.scene.render.image_settings.file_format
        if options.enabled and file_format != settings.MULTILAYER:
            column.label(text=f"Output format {file_format}: use OpenEXR MultiLayer", icon="ERROR")
        try:
            locate.import_batch(preferences.module_dir(context))
            column.label(text=f"Module: {locate.loaded_from()}", icon="CHECKMARK")
        except ImportError:
            column.label(text="Module not found: see the add-on's preferences", icon="ERROR")


def register():
    bpy.utils.register_class(RENDER_PT_mcdenoise)


def unregister():
    bpy.utils.unregister_class(RENDER_PT_mcdenoise)
