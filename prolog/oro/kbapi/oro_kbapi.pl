:- module(oro_kbapi,
          [ oro_kbapi_start/2,          % +Options, -Listener
            oro_kbapi_stop/1,           % +Listener
            oro_kbapi_port/2,           % +Listener, -Port
            oro_kbapi_connections/2     % +Listener, -Count
          ]).
:- use_module(library(socket)).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(lists)).
:- use_module(library(http/json)).
:- use_module(library(oro/server/oro_protocol)).
:- use_module(library(oro/kbapi/oro_kbapi_methods)).

/** <module> The KB-API dialect: knowledge_core and pykb clients

minimalkb and knowledge_core, ORO's successors, speak the *KB-API* over
a socket framed like ORO's: a method line, one line per parameter and
`#end#`.  Their parameters and replies are JSON:

  - every parameter line is one JSON value; an optional last line
    `{"kwargs": {...}}` holds keyword arguments;
  - a reply is `ok`, one line of JSON and `#end#` (`ok` and `#end#`
    alone when there is nothing to return);
  - an error is `error`, `kberror` and a one-line message (which
    starts with the ORO exception's short name);
  - an event is `event`, the subscription id (`evt_...`) and a JSON
    list of bindings;
  - `close` ends the connection without a reply.

The dialect is served on a port of its own (`--kb-port`, 6971 on the
command line): the ORO protocol's parameters are often valid JSON too
(`["a b c"]`), so a request cannot tell its dialect, and ORO clients
on port 6969 must see no change.  Both listeners serve the same store,
so facts, models and events are shared by ORO and KB-API clients.

The framing is oro_protocol's reader (strict UTF-8, `max_request_size`
bytes at most); the methods are in oro_kbapi_methods.  Each connection
is served by a thread of its own, at most `max_connections` at once;
setup_call_cleanup/3 releases its socket and its subscriptions
whatever happens.
*/

:- setting(max_connections, positive_integer, 64,
           'Maximum number of simultaneous KB-API connections').
:- setting(max_request_size, positive_integer, 16777216,
           'Maximum size of one KB-API request, in bytes').

:- dynamic
    listening/1,                    % Listener socket
    connections/2.                  % Listener socket, Count

%!  oro_kbapi_start(+Options, -Listener) is det.
%
%   Listen for KB-API clients.  Options: port(Port) (0 picks a free
%   port, as tests must), host(Host) (default '127.0.0.1').  Listener
%   is an opaque handle for oro_kbapi_port/2 and oro_kbapi_stop/1.
%
%   @error type_error(between(0, 65535), Port) for a bad port.

oro_kbapi_start(Options, Listener) :-
    must_be(list, Options),
    option(port(Port0), Options, 6971),
    must_be(between(0, 65535), Port0),
    option(host(Host), Options, '127.0.0.1'),
    (   Port0 =:= 0
    ->  true                                % tcp_bind/2 picks it
    ;   Port = Port0
    ),
    tcp_socket(Socket),
    tcp_setopt(Socket, reuseaddr),
    tcp_bind(Socket, Host:Port),
    tcp_listen(Socket, 64),
    with_mutex(oro_kbapi,
               ( assertz(listening(Socket)),
                 assertz(connections(Socket, 0))
               )),
    thread_create(accept_loop(Socket), Accept, []),
    Listener = oro_kbapi{socket:Socket, host:Host, port:Port,
                         accept:Accept},
    debug(oro(kbapi), 'KB-API listening on ~w:~w', [Host, Port]).

%!  oro_kbapi_port(+Listener, -Port) is det.
%
%   The port Listener listens on.

oro_kbapi_port(Listener, Port) :-
    must_be(dict, Listener),
    Port = Listener.port.

%!  oro_kbapi_connections(+Listener, -Count) is det.
%
%   Count is the number of KB-API connections Listener is serving,
%   also after it stopped listening.

oro_kbapi_connections(Listener, Count) :-
    must_be(dict, Listener),
    (   with_mutex(oro_kbapi, connections(Listener.socket, Count0))
    ->  Count = Count0
    ;   Count = 0
    ).

%!  oro_kbapi_stop(+Listener) is det.
%
%   Stop accepting KB-API connections and release the port.
%   Connections in progress go on until their clients leave.

oro_kbapi_stop(Listener) :-
    must_be(dict, Listener),
    Socket = Listener.socket,
    with_mutex(oro_kbapi,
               ( retractall(listening(Socket)),
                 (   connections(Socket, 0)
                 ->  retractall(connections(Socket, _))
                 ;   true
                 )
               )),
    wake_acceptor(Listener),
    thread_join(Listener.accept, _),
    catch(tcp_close_socket(Socket), _, true).

%   The accept thread is woken by a connection of our own once the
%   listener is marked stopped, and ends.

wake_acceptor(Listener) :-
    (   memberchk(Listener.host, ['0.0.0.0', '::', ''])
    ->  Host = '127.0.0.1'
    ;   Host = Listener.host
    ),
    catch(setup_call_cleanup(tcp_connect(Host:Listener.port, Stream, []),
                             true,
                             close(Stream, [force(true)])),
          _,
          thread_signal(Listener.accept, throw(oro_kbapi_stop))).

accept_loop(Socket) :-
    catch(accept_connections(Socket), oro_kbapi_stop, true).

accept_connections(Socket) :-
    repeat,
    tcp_accept(Socket, Client, Peer),
    (   \+ with_mutex(oro_kbapi, listening(Socket))
    ->  !,
        tcp_close_socket(Client)
    ;   start_connection(Socket, Client, Peer),
        fail
    ).

start_connection(Socket, Client, Peer) :-
    setting(max_connections, Max),
    with_mutex(oro_kbapi, reserve(Socket, Max, Reserved)),
    (   Reserved == true
    ->  catch(thread_create(serve_connection(Socket, Client, Peer), _,
                            [detached(true)]),
              Error,
              ( release(Socket),
                refuse(Client, Error)
              ))
    ;   refuse(Client, too_many)
    ).

reserve(Socket, Max, Reserved) :-
    (   connections(Socket, N),
        N < Max
    ->  retract(connections(Socket, N)),
        N1 is N + 1,
        assertz(connections(Socket, N1)),
        Reserved = true
    ;   Reserved = false
    ).

release(Socket) :-
    with_mutex(oro_kbapi,
               (   retract(connections(Socket, N))
               ->  N1 is N - 1,
                   (   N1 =:= 0,
                       \+ listening(Socket)
                   ->  true                 % stopped, and none left
                   ;   assertz(connections(Socket, N1))
                   )
               ;   true
               )).

refuse(Client, Why) :-
    debug(oro(kbapi), 'KB-API connection refused: ~q', [Why]),
    catch(setup_call_cleanup(
              tcp_open_socket(Client, Pair),
              ( stream_pair(Pair, _, Out),
                set_stream(Out, encoding(utf8)),
                oro_write_error(Out, kberror,
                                "OntologyServerException: Too many \c
                                 connections: try again later.")
              ),
              close(Pair, [force(true)])),
          _, true).

		 /*******************************
		 *          CONNECTION          *
		 *******************************/

%   The connection's context: its output stream and the mutex every
%   write to it holds, so that replies and events never interleave.
%   Its subscriptions are released when it ends, however it ends.

serve_connection(Socket, Client, Peer) :-
    setup_call_cleanup(
        tcp_open_socket(Client, Pair),
        serve_stream(Pair, Peer),
        ( close(Pair, [force(true)]),
          release(Socket)
        )).

serve_stream(Pair, Peer) :-
    stream_pair(Pair, In, Out),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)),
    debug(oro(kbapi), 'KB-API connection from ~q', [Peer]),
    setting(max_request_size, Limit),
    setup_call_cleanup(
        ( mutex_create(Mutex),
          kb_connection_open(Out, Mutex, Context)
        ),
        catch(( oro_reader(In, Reader, [max_request_size(Limit)]),
                serve_requests(Context, Reader)
              ),
              Error,
              debug(oro(kbapi), 'KB-API connection ~q ended: ~q',
                    [Peer, Error])),
        ( kb_connection_closed(Context),
          mutex_destroy(Mutex)
        )).

serve_requests(Context, Reader0) :-
    oro_read_request(Reader0, Request, Reader),
    (   serve_request(Request, Context)
    ->  serve_requests(Context, Reader)
    ;   true
    ).

%   serve_request(+Request, +Context) is semidet: fails when the
%   connection must end.

serve_request(end_of_file, _) :-
    !,
    fail.
serve_request(bad(too_large(Limit)), Context) :-
    !,
    format(string(Message), "OntologyServerException: Request larger \c
                             than ~D bytes: closing the connection.",
           [Limit]),
    send(Context, error(Message)),
    fail.
serve_request(bad(encoding), Context) :-
    !,
    send(Context, error("IllegalArgumentException: The request is not \c
                         valid UTF-8.")).
serve_request(help, Context) :-
    !,
    serve_request(request("help", []), Context).
serve_request(request(Method, _), _) :-
    string_lower(Method, "close"),
    !,
    fail.
serve_request(request(Method, Lines), Context) :-
    catch(json_params(Lines, Args, KWArgs), Error, true),
    (   var(Error)
    ->  kb_dispatch(Context, Method, Args, KWArgs, Reply)
    ;   kb_error_reply(Error, Reply)
    ),
    send(Context, Reply).

send(Context, Reply) :-
    with_mutex(Context.mutex, write_reply(Reply, Context.out)).

write_reply(ok(void), Out) :-
    !,
    write(Out, "ok\n#end#\n"),
    flush_output(Out).
write_reply(ok(Value), Out) :-
    with_output_to(string(JSON),
                   json_write_dict(current_output, Value, [width(0)])),
    oro_write_ok(Out, raw(JSON)).
write_reply(error(Message), Out) :-
    oro_write_error(Out, kberror, Message).

%   json_params(+Lines, -Args, -KWArgs): each line is one JSON value; a
%   last one {"kwargs": Dict} gives the keyword arguments.

json_params(Lines, Args, KWArgs) :-
    maplist(json_param, Lines, Values),
    (   append(Args0, [Last], Values),
        is_dict(Last),
        dict_pairs(Last, _, [kwargs-KWArgs0]),
        is_dict(KWArgs0)
    ->  Args = Args0,
        KWArgs = KWArgs0
    ;   Args = Values,
        KWArgs = _{}
    ).

json_param(Line, Value) :-
    catch(atom_json_dict(Line, Value, [value_string_as(string)]),
          _,
          throw(error(domain_error(kb_json_parameter, Line), _))).
