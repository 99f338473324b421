"""frame.py: denoises one frame file with mcdtool's own per-frame code,
through mcdenoise.batch.run_frames (so the file equals `mcdtool FILE CHAIN -o
OUT`'s, written atomically); never raises for the frame's failure."""
import os

from . import locate, options


def denoise_file(frame_file, mode, output, pattern, module_dir="", light_passes=False):
    """Denoises `frame_file` (with its light passes when `light_passes`);
    returns (ok, message) for the reports."""
    args = options.command_line(frame_file, mode, output, pattern, light_passes)
    target = args[args.index("-o") + 1]
    try:
        batch = locate.import_batch(module_dir)
        os.makedirs(os.path.dirname(target) or ".", exist_ok=True)
    except (ImportError, OSError) as error:
        return False, f"{frame_file}: not denoised: {error}"
    result = batch.run_frames(args, [None], retries=0)[0]
    if result.status != "written":
        return False, f"{frame_file}: not denoised: {result.message}"
    where = "in place" if output == "IN_PLACE" else f"to {target}"
    return True, f"{os.path.basename(frame_file)} denoised {where} ({result.seconds:.2f} s)"
