"""mcdenoise: Monte Carlo render denoising on OpenImageIO, from Python.

Every filter and metric of libmcdenoise, with the library's names, argument
names, defaults and doc comments (see docs/filters.md and the C++ headers):

    import OpenImageIO as oiio, mcdenoise
    beauty = oiio.ImageBuf("render.exr")          # or a numpy array (H, W, C)
    clean = mcdenoise.gaussian(mcdenoise.object_median(beauty, ids, size=7), size=3)

Images are OpenImageIO.ImageBuf objects (used in place, no copy) or numpy
arrays of shape (H, W) or (H, W, C); a filter returns the kind its first image
came in. The GIL is released while the library runs. A library error raises
mcdenoise.Error with the library's message; a malformed mcdtool command line
raises mcdenoise.UsageError.

`mcdenoise.__version__` is the loaded library's version ("0.2.0").

Frame-sequence batch denoise (local process pool or Dask) is in
mcdenoise.batch; see docs/python.md.
"""
from ._mcdenoise import *  # noqa: F401,F403 (the bound library, mcdenoise.Error, UsageError, ... is the API)
from ._mcdenoise import __version__  # noqa: F401 (the loaded libmcdenoise's version, "major.minor.patch")
