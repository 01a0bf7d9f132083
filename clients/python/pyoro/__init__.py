"""pyoro: a Python client of the ORO knowledge server.

    from pyoro import Oro, OroServerError

    with Oro("localhost", 6969) as oro:
        oro += "hrp2 rdf:type Robot"
        print(oro["* rdf:type Robot"])

The server's methods are methods of the ``Oro`` object (built from the
server's ``listSimpleMethods``); see ``Oro`` for the conveniences
(``oro[...]``, ``in``, ``+=``, ``-=``, ``subscribe``), threads and
timeouts.  Log messages go to the ``pyoro`` logger.
"""

from .client import Oro, OroConnectionError, OroServerError, OroTimeout
from .wire import IdList, quote

__all__ = ["Oro", "OroServerError", "OroConnectionError", "OroTimeout", "IdList", "quote"]
__version__ = "1.0.0"
