name(oro).
version('0.1.0').
title('Knowledge server for cognitive robots, speaking the ORO protocol').
author('The oro authors', 'oro@kb.openrobots.org').
home('http://kb.openrobots.org').
keywords([rdf, owl, robotics, knowledge_base, oro]).
