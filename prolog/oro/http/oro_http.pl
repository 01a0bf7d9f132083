:- module(oro_http,
          [ oro_http_start/2,           % +Options, -Http
            oro_http_stop/1,            % +Http
            oro_http_port/2             % +Http, -Port
          ]).
:- use_module(library(http/thread_httpd)).
:- use_module(library(http/http_dispatch)).
:- use_module(library(http/html_write)).
:- use_module(library(option)).
:- use_module(library(error)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(lists)).
:- use_module(library(semweb/rdf_db), [rdf_graph_property/2]).
:- use_module(library(oro/sparql/oro_sparql), [oro_sparql_graph/2]).
:- use_module(library(oro/oro_store), [oro_graph_layer/3, oro_store_read/1]).
:- use_module(library(oro/http/oro_http_sparql)).
:- use_module(library(oro/http/oro_http_pengines)).
:- use_module(library(oro/http/oro_http_inspector)).
:- use_module(library(oro/http/oro_http_feed), [oro_feed_stop/0]).

/** <module> The HTTP side of oro: SPARQL endpoint and Pengines

An HTTP server (SWI-Prolog's thread_httpd) next to the ORO socket
server, serving the same store, read-only:

  - `/`: the web inspector (oro_http_inspector);
  - `/sparql`: the SPARQL 1.1 Protocol endpoint (oro_http_sparql);
  - `/graphs`: a page listing the graphs a SPARQL dataset can name;
  - `/pengine/...`: Pengines, for Prolog planners in other processes
    (oro_http_pengines).

The handlers are declared when this module loads (http_handler/3
declarations, as every SWI-Prolog HTTP application does); no socket
is opened before oro_http_start/2.  The server of library(oro_server)
starts it with its `http` options.
*/

:- setting(workers, positive_integer, 4,
           'Threads serving HTTP requests').

:- http_handler(root(graphs), graphs_page, []).

%!  oro_http_start(+Options, -Http) is det.
%
%   Start an HTTP server.  Options:
%
%     - port(Port): the port (0, the default, picks a free one);
%     - host(Host): the address to listen on (default `127.0.0.1`);
%     - changes(Bool): whether Pengines may change the store (default
%       `false`: see oro_http_pengines).
%
%   Http is an opaque handle.  The server accepts connections when this
%   predicate returns.
%
%   @error domain_error(port, Port) if Port is over 65535.

oro_http_start(Options, Http) :-
    must_be(list, Options),
    option(port(Port0), Options, 0),
    must_be(nonneg, Port0),
    (   Port0 =< 65535
    ->  true
    ;   domain_error(port, Port0)
    ),
    option(host(Host), Options, '127.0.0.1'),
    must_be(atom, Host),
    option(changes(Changes), Options, false),
    must_be(boolean, Changes),
    set_setting(oro_http_pengines:changes, Changes),
    (   Port0 =:= 0
    ->  true
    ;   Port = Port0
    ),
    setting(workers, Workers),
    http_server(http_dispatch,
                [port(Host:Port), workers(Workers), silent(true)]),
    Http = oro_http{host:Host, port:Port},
    debug(oro(http), 'HTTP listening on ~w:~w', [Host, Port]).

%!  oro_http_port(+Http, -Port) is det.
%
%   The port the server Http listens on.

oro_http_port(Http, Port) :-
    Port = Http.port.

%!  oro_http_stop(+Http) is det.
%
%   Stop the server Http and release its port, and the inspector's
%   live feed (oro_feed_stop/0).

oro_http_stop(Http) :-
    http_stop_server(Http.host:Http.port, []),
    oro_feed_stop.

		 /*******************************
		 *            PAGES             *
		 *******************************/

graphs_page(_Request) :-
    oro_store_read(findall(Row, graph_row(Row), Rows)),
    reply_html_page(title('oro: graphs'),
                    [ h1('Graphs'),
                      p(['Each can be named by FROM, FROM NAMED, GRAPH or the ',
                         code('default-graph-uri'), ' and ',
                         code('named-graph-uri'), ' parameters of ',
                         a(href(sparql), '/sparql'), '.']),
                      table([border(1)],
                            [ tr([th('Graph IRI'), th('Holds'), th('Triples')])
                            | Rows
                            ])
                    ]).

graph_row(tr([td(code(IRI)), td(What), td(Count)])) :-
    oro_sparql_graph(IRI, Graph),
    (   oro_graph_layer(Graph, Model, profile(Profile))
    ->  format(atom(What), 'model ~w, memory profile ~w', [Model, Profile])
    ;   What = 'ontology file'
    ),
    (   rdf_graph_property(Graph, triples(Count))
    ->  true
    ;   Count = 0
    ).
