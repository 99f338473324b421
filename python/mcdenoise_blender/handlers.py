"""handlers.py: denoises each frame file right after Blender writes it
(bpy.app.handlers.render_write: `blender -b -f` stills and animations alike),
prepares the scene when a render starts (render_init) and sums up when it
ends (render_complete, render_cancel). A failure is reported, never raised:
Blender goes on rendering."""
import time

import bpy
from bpy.app.handlers import persistent

from . import frame, preferences, reports, settings


class _RenderState:
    """What the current render does and has done."""

    def __init__(self, active=False, module_dir=""):
        self.active = active
        self.module_dir = module_dir
        self.denoised = 0
        self.failed = 0
        self.started = time.perf_counter()


_state = _RenderState()


@persistent
def _on_render_init(scene, *_):
    global _state
    _state = _RenderState()
    if not scene.mcdenoise.enabled:
        return
    try:
        _state = _RenderState(settings.prepare_scene(scene), preferences.module_dir())
    except Exception as error:  # a handler must not stop the render
        reports.report("ERROR", f"frames will not be denoised: {error}")


@persistent
def _on_render_write(scene, *_):
    options = scene.mcdenoise
    if not (_state.active and options.enabled):
        return
    number = scene.frame_current
    try:
        path = bpy.path.abspath(scene.render.frame_path(frame=number))
        ok, message = frame.denoise_file(path, options.mode, options.output, options.pattern, _state.module_dir,
                                         options.light_passes)
    except Exception as error:  # a handler must not stop the render
        ok, message = False, f"{type(error).__name__}: {error}"
    if ok:
        _state.denoised += 1
    else:
        _state.failed += 1
    done = _state.denoised + _state.failed
    reports.report("INFO" if ok else "ERROR", f"frame {number} ({done} done): {message}")


@persistent
def _on_render_end(scene, *_):
    if not _state.active:
        return
    _state.active = False
    seconds = time.perf_counter() - _state.started
    reports.report("WARNING" if _state.failed else "INFO",
                   f"{_state.denoised} frame(s) denoised, {_state.failed} failed, in {seconds:.1f} s")


_HANDLERS = (
    (bpy.app.handlers.render_init, _on_render_init),
    (bpy.app.handlers.render_write, _on_render_write),
    (bpy.app.handlers.render_complete, _on_render_end),
    (bpy.app.handlers.render_cancel, _on_render_end),
)


def register():
    for handlers, function in _HANDLERS:
        handlers.append(function)


def unregister():
    for handlers, function in _HANDLERS:
        if function in handlers:
            handlers.remove(function)
