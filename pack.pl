name(oro).
version('0.1.0').
title('Knowledge server for cognitive robots, speaking the ORO protocol').
keywords([rdf, owl, robotics, knowledge_base, oro]).
author('The oro authors', 'oro@kb.openrobots.org').
maintainer('The oro authors', 'oro@kb.openrobots.org').
packager('The oro authors', 'oro@kb.openrobots.org').
home('http://kb.openrobots.org').
download('http://kb.openrobots.org/oro/oro-*.tgz').
requires(prolog >= '9.0.4').
