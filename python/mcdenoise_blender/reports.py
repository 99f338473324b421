"""reports.py: the add-on's messages, from any thread, to the console and to
Blender's reports (the Info log; in the UI the last one is also the status
bar's text for a few seconds).

Render handlers run on the render job's thread in the UI, where operators
must not be called: there a message is queued, and a timer on the main
thread hands the queue to a modal operator, whose reports Blender keeps (and
prints to the console). In background mode (`blender -b`) the render runs on
the main thread and a message is reported at once by an operator, which
Blender prints to the console."""
import queue
import threading

import bpy

PREFIX = "mcdenoise: "
#: Seconds between the UI timer's looks at the queue.
FLUSH_INTERVAL = 0.25
#: Seconds the last message stays in the status bar.
STATUS_SECONDS = 10.0

_pending = queue.SimpleQueue()


def report(level, message):
    """Reports `message` ('INFO', 'WARNING' or 'ERROR'); never raises."""
    text = PREFIX + message
    if not bpy.app.background:
        _pending.put((level, text))  # reported, and printed by Blender, on the main thread
    elif threading.current_thread() is threading.main_thread():
        try:
            bpy.ops.mcdenoise.report(level=level, message=text)
        except RuntimeError:
            pass  # an ERROR report raises once Blender has printed it
    else:
        print(f"{level.capitalize()}: {text}", flush=True)


class MCDENOISE_OT_report(bpy.types.Operator):
    """Reports one message (background mode: printed to the console)"""
    bl_idname = "mcdenoise.report"
    bl_label = "mcdenoise Report"
    bl_options = {"INTERNAL"}

    level: bpy.props.StringProperty(default="INFO")
    message: bpy.props.StringProperty()

    def execute(self, context):
        self.report({self.level}, self.message)
        return {"FINISHED"}


class MCDENOISE_OT_show_reports(bpy.types.Operator):
    """Reports the queued messages from a modal step, so they reach the Info log, and shows the last in the status bar"""
    bl_idname = "mcdenoise.show_reports"
    bl_label = "mcdenoise Show Reports"
    bl_options = {"INTERNAL"}

    def invoke(self, context, event):
        self._timer = context.window_manager.event_timer_add(0.01, window=context.window)
        context.window_manager.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        context.window_manager.event_timer_remove(self._timer)
        messages = []
        while not _pending.empty():
            messages.append(_pending.get())
        for level, text in messages:
            self.report({level}, text)
        if messages:
            context.workspace.status_text_set(messages[-1][1])
            if bpy.app.timers.is_registered(_clear_status):
                bpy.app.timers.unregister(_clear_status)
            bpy.app.timers.register(_clear_status, first_interval=STATUS_SECONDS)
        return {"FINISHED"}


def _clear_status():
    for workspace in bpy.data.workspaces:
        workspace.status_text_set(None)


def _flush():
    """UI timer: starts the modal reporter when messages are waiting."""
    window_manager = bpy.context.window_manager
    if not _pending.empty() and window_manager and window_manager.windows:
        try:
            with bpy.context.temp_override(window=window_manager.windows[0]):
                bpy.ops.mcdenoise.show_reports("INVOKE_DEFAULT")
        except RuntimeError as error:
            print(f"{PREFIX}cannot show reports: {error}", flush=True)
    return FLUSH_INTERVAL


_CLASSES = (MCDENOISE_OT_report, MCDENOISE_OT_show_reports)


def register():
    for cls in _CLASSES:
        bpy.utils.register_class(cls)
    if not bpy.app.background:
        bpy.app.timers.register(_flush, first_interval=FLUSH_INTERVAL, persistent=True)


def unregister():
    if bpy.app.timers.is_registered(_flush):
        bpy.app.timers.unregister(_flush)
    for cls in reversed(_CLASSES):
        bpy.utils.unregister_class(cls)
