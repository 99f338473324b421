"""locate.py: finds and imports the compiled mcdenoise package (mcdenoise and
mcdenoise.batch, built for Debian's Python 3.11, which is Blender's).

Searched in order: the folder set in the add-on's preferences, the build
folder recorded in the zip when it was built (build_config.MODULE_DIR), then
Blender's sys.path (e.g. a package installed into dist-packages)."""
import os
import sys

from . import build_config


class ModuleMissing(ImportError):
    """The compiled package was found nowhere; the message says where it looked."""


def candidate_dirs(preference_dir):
    """The folders tried before sys.path, in order (empty ones left out)."""
    return [d for d in (preference_dir, build_config.MODULE_DIR) if d]


def import_batch(preference_dir=""):
    """mcdenoise.batch, imported from the first folder of `candidate_dirs`
    that holds a mcdenoise package, else from sys.path. Once imported, the
    package stays for the session (Python imports a module once)."""
    if "mcdenoise.batch" in sys.modules:
        return sys.modules["mcdenoise.batch"]
    for directory in candidate_dirs(preference_dir):
        if os.path.isfile(os.path.join(directory, "mcdenoise", "__init__.py")):
            if directory not in sys.path:
                sys.path.insert(0, directory)
            break
    try:
        import mcdenoise.batch
    except ImportError as error:
        searched = ", ".join(candidate_dirs(preference_dir) + ["sys.path"])
        raise ModuleMissing(f"cannot import the compiled mcdenoise module (searched {searched}): {error}; "
                            "set its folder in Preferences > Add-ons > mcdenoise") from error
    return mcdenoise.batch


def loaded_from():
    """The folder the package was imported from, or '' if it is not loaded."""
    module = sys.modules.get("mcdenoise")
    return os.path.dirname(os.path.dirname(module.__file__)) if module else ""
