"""The one catalogue of problem codes: ``API1xx`` (HTTP API), ``NET0xx`` (raised by the browser
client when no API answer arrives); ``STL1xx``, ``SCL2xx``, ``SIM5xx`` later.

Every problem Nasaq reports carries a stable code, a message key and parameters, so the UI can show
it in any of its languages and lessons can key hints to it. The English templates live in
``*.csv`` files beside this package; the front end's catalogues translate the keys.
"""

from nasaq.diagnostics.catalogue import CatalogueEntry, entry, render
from nasaq.diagnostics.model import Diagnostic, Severity, Span

__all__ = ["CatalogueEntry", "Diagnostic", "Severity", "Span", "entry", "render"]
