"""operator.py: Image editor > Image > Denoise EXR Sequence: denoises the
chosen existing EXR frame files with the same options as the render panel,
one after the other, with progress and a report per frame."""
import os

import bpy

from . import frame, options, preferences


class MCDENOISE_OT_denoise_sequence(options.DenoiseOptions, bpy.types.Operator):
    """Denoise existing OpenEXR MultiLayer frames with mcdenoise"""
    bl_idname = "mcdenoise.denoise_sequence"
    bl_label = "Denoise EXR Sequence"

    directory: bpy.props.StringProperty(subtype="DIR_PATH", options={"HIDDEN", "SKIP_SAVE"})
    files: bpy.props.CollectionProperty(type=bpy.types.OperatorFileListElement, options={"HIDDEN", "SKIP_SAVE"})
    filter_glob: bpy.props.StringProperty(default="*.exr", options={"HIDDEN"})

    def invoke(self, context, event):
        context.window_manager.fileselect_add(self)
        return {"RUNNING_MODAL"}

    def execute(self, context):
        names = sorted(f.name for f in self.files if f.name)
        if not names:
            self.report({"ERROR"}, "mcdenoise: no frame files chosen")
            return {"CANCELLED"}
        window_manager = context.window_manager
        window_manager.progress_begin(0, len(names))
        failed = 0
        try:
            for done, name in enumerate(names, 1):
                path = os.path.join(bpy.path.abspath(self.directory), name)
                ok, message = frame.denoise_file(path, self.mode, self.output, self.pattern,
                                                 preferences.module_dir(context), self.light_passes)
                failed += not ok
                self.report({"INFO" if ok else "ERROR"}, f"mcdenoise: {done}/{len(names)}: {message}")
                window_manager.progress_update(done)
        finally:
            window_manager.progress_end()
        self.report({"WARNING" if failed else "INFO"},
                    f"mcdenoise: {len(names) - failed} of {len(names)} frame(s) denoised")
        return {"FINISHED"}


def _menu_entry(self, context):
    self.layout.separator()
    self.layout.operator(MCDENOISE_OT_denoise_sequence.bl_idname, icon="IMAGE_DATA")


def register():
    bpy.utils.register_class(MCDENOISE_OT_denoise_sequence)
    bpy.types.IMAGE_MT_image.append(_menu_entry)


def unregister():
    bpy.types.IMAGE_MT_image.remove(_menu_entry)
    bpy.utils.unregister_class(MCDENOISE_OT_denoise_sequence)
