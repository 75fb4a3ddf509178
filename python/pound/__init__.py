"""pound: seismic pounding analysis from Python.

The same models, records, validation and results as the ``pound`` program, in process::

    import pound
    model = pound.Model.from_file("models/two_sdof_girders.json")
    result = pound.run(model)
    result.links["joint"]["force"]          # NumPy array, one value per recorded step

See docs/python.md for the whole interface.
"""

from pound.errors import AnalysisError, InputError, OutputError
from pound.model import Model
from pound.pushover import Pushover
from pound.record import Record
from pound.result import Result
from pound.runs import batch, run
from pound import verify

__all__ = ["AnalysisError", "InputError", "OutputError", "Model", "Pushover", "Record", "Result",
           "batch", "run", "verify"]
__version__ = "0.1.0"
