"""preferences.py: the add-on's preference, the folder that holds the
compiled mcdenoise package (left empty: the build folder recorded in the zip,
then sys.path)."""
import bpy

from . import build_config, locate


def module_dir(context=None):
    """The module folder set in the preferences ('' when unset)."""
    context = context or bpy.context
    addon = context.preferences.addons.get(__package__)
    return bpy.path.abspath(addon.preferences.module_dir) if addon else ""


class McdenoisePreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_dir: bpy.props.StringProperty(
        name="Module folder", subtype="DIR_PATH",
        description="Folder holding the compiled mcdenoise package (a build's python/ folder); "
                    "empty: the build folder recorded in the add-on, then Python's path")

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "module_dir")
        layout.label(text=f"Recorded build folder: {build_config.MODULE_DIR or '(none)'}")
        loaded = locate.loaded_from()
        layout.label(text=f"Loaded from: {loaded}" if loaded else "Not loaded yet (loads on first use)")


def register():
    bpy.utils.register_class(McdenoisePreferences)


def unregister():
    bpy.utils.unregister_class(McdenoisePreferences)
