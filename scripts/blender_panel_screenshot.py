"""blender_panel_screenshot.py: run by scripts/blender-panel-screenshot in
Debian's Blender under Xvfb. Installs the add-on zip, sets up a small Cycles
animation with mcdenoise enabled, renders it from the UI (the render job's
thread, as a user's Ctrl+F12: the add-on's reports go to the Info log and
the status bar), then saves a screenshot of the Render Properties, full
window, with the mcdenoise panel and the status bar, and quits.

    blender --factory-startup --python blender_panel_screenshot.py -- ZIP OUTPUT_DIR PNG
"""
import os
import sys

import addon_utils
import bpy

ZIP, OUTPUT_DIR, PNG = sys.argv[sys.argv.index("--") + 1:]


def set_up_scene(scene):
    bpy.ops.preferences.addon_install(filepath=ZIP, overwrite=True)
    addon_utils.enable("mcdenoise_blender", default_set=True)
    bpy.context.preferences.view.render_display_type = "NONE"
    bpy.context.preferences.view.show_splash = False
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 8
    scene.render.resolution_x, scene.render.resolution_y = 96, 64
    scene.frame_start, scene.frame_end = 1, 2
    scene.render.filepath = os.path.join(OUTPUT_DIR, "frame_####")
    scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
    scene.mcdenoise.output = "PATTERN"
    scene.mcdenoise.enabled = True


def properties_area():
    """The window and its largest area, which becomes Render Properties."""
    window = bpy.context.window_manager.windows[0]
    area = max(window.screen.areas, key=lambda a: a.width * a.height)
    return window, area


def render():
    window, area = properties_area()
    with bpy.context.temp_override(window=window, area=area):
        bpy.ops.render.render("INVOKE_DEFAULT", animation=True)
    return None


def after_render():
    if bpy.app.is_job_running("RENDER"):
        return 0.5
    properties_area()[1].type = "PROPERTIES"
    bpy.app.timers.register(step(show_render_tab), first_interval=0.5)
    return None


def show_render_tab():
    # Only once the new Properties editor has been drawn does it know its tabs.
    properties_area()[1].spaces[0].context = "RENDER"
    bpy.app.timers.register(step(screenshot), first_interval=1.0)
    return None


def screenshot():
    window = bpy.context.window_manager.windows[0]
    with bpy.context.temp_override(window=window):
        bpy.ops.screen.screenshot(filepath=PNG)
    bpy.ops.wm.quit_blender()
    return None


def step(function):
    """A timer step that quits Blender (status 1) on an error, rather than hang."""
    def run():
        try:
            return function()
        except Exception as error:
            print(f"blender_panel_screenshot.py: {function.__name__}: {error}", flush=True)
            os._exit(1)
    return run


set_up_scene(bpy.context.scene)
bpy.app.timers.register(step(render), first_interval=2.0)
bpy.app.timers.register(step(after_render), first_interval=3.0)
