:- module(oro_server,
          [ oro_server_start/2,         % +Options, -Server
            oro_server_stop/1,          % +Server
            oro_server_shutdown/1,      % +Server
            oro_server_port/2,          % +Server, -Port
            oro_server_connections/2,   % +Server, -Count
            oro_server_http_port/2,     % +Server, -Port
            oro_server_kb_port/2,       % +Server, -Port
            oro_server_main/0,
            oro_server_main/1,          % +Argv
            oro_server_arguments/1      % -Argv
          ]).
%   This library's modules import each other as library(oro/...): when
%   prolog/ is not on the library path yet (a checkout used without
%   installing the pack), put it there.

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.
:- prolog_load_context(directory, Dir),
   (   user:file_search_path(library, Dir)
   ->  true
   ;   asserta(user:file_search_path(library, Dir))
   ).
:- use_module(library(socket)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(error)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(aggregate)).
:- use_module(library(apply), [include/3]).
:- use_module(library(lists), [delete/3, append/3]).
:- use_module(library(oro)).
:- use_module(library(oro/server/oro_protocol)).
:- use_module(library(oro/server/oro_methods)).
:- use_module(library(oro/server/oro_methods_sparql)).
:- use_module(library(oro/server/oro_methods_categorization)).
:- use_module(library(oro/server/oro_methods_explain)).
:- use_module(library(oro/server/oro_plugins)).
:- use_module(library(oro/kbapi/oro_kbapi)).
:- use_module(library(oro/server/oro_log)).
:- use_module(library(oro/server/oro_cli)).
:- use_module(library(oro/oro_save), [oro_save_cancel/0]).
:- use_module(library(oro/http/oro_http)).
:- use_module(library(oro/replication/oro_redis), [oro_redis_options/1, oro_redis_stop/0]).

/** <module> The ORO socket server

    swipl server/oro_server.pl [--port=N] [--host=ADDR] [--ontology=FILE]...
                               [--no-commonsense] [--robot-id=ID]
                               [--time-base=MS] [--save-dir=DIR] [--plugin=FILE]...
                               [--db=DIR] [--kb-port=N|--no-kb]
                               [--min-reply-latency=MS] [--events-before-reply]

An accept thread hands each connection to a worker thread, at most
`max_connections` at once; each worker reads requests with
oro_protocol, runs them through oro_methods and writes the replies,
then waits for the next connection.  Requests from
different clients run concurrently (changes are serialised by the
store); a slow or broken client only holds its own worker.  Every
connection is closed and released by setup_call_cleanup/3, whatever
happens.

The server starts from oro_server_main/0,1 (the command line: the
script server/oro_server.pl, or `swipl -g oro_server_main` once
library(oro_server) is loaded) or oro_server_start/2 (tests,
embedding); loading this library starts nothing.
*/

:- dynamic
    connection/1,                   % Mutex of a live connection
    closed_connection/1,            % Mutex of one the shutdown closed
    workers/3,                      % Jobs, Busy, Idle: see CONNECTION WORKERS
    from_address/3.                 % Jobs, Host, Count: see CONNECTION WORKERS

:- setting(port, between(0, 65535), 6969,
           'TCP port the command line listens on (0: a free one)').
:- setting(host, atom, '127.0.0.1',
           'Address the command line listens on').
:- setting(rebuild_garbage, nonneg, 1000000,
           'Value of oro_store:rebuild_garbage for the command line').
:- setting(max_connections, positive_integer, 256,
           'Maximum number of simultaneous client connections').
:- setting(spare_workers, nonneg, 4,
           'Connection threads made at start and kept waiting for a client').
:- setting(max_request_size, positive_integer, 16777216,
           'Maximum size of one request, in bytes').
:- setting(max_params, positive_integer, 4096,
           'Maximum number of parameters of one request').
:- setting(shutdown_grace, number, 10,
           'Seconds a shutdown waits for the request in progress of a connection').
:- setting(max_per_address, nonneg, 64,
           'Maximum number of simultaneous connections from one client \c
            address (0: no limit)').
:- setting(idle_timeout, number, 30,
           'Seconds a connection that never registered an event may \c
            wait without sending a request before it is closed \c
            (0: never)').
:- setting(write_timeout, number, 60,
           'Seconds a reply may wait for a client that does not read, before \c
           the client is disconnected').
:- setting(event_queue, positive_integer, 10000,
           'Events a connection may have waiting to be written; a client \c
           further behind is disconnected (its watchers are released)').
:- setting(events_before_reply, boolean, false,
           'Write the events a request fires for its own connection before \c
           its reply (in the same write) rather than after it; for liboro \c
           (see README, Clients)').
:- setting(min_reply_latency, nonneg, 0,
           'Milliseconds a reply waits at least after its request was read \c
           (0: none); for unpatched liboro builds, which lose a reply that \c
           comes too fast (see README, Clients)').

opt_type(port, port, between(0, 65535)).
opt_type(host, host, atom).
opt_type(ontology, ontology, file(read)).
opt_type(commonsense, commonsense, boolean).
opt_type(robot_id, robot_id, atom).
opt_type(time_base, time_base, natural).
opt_type(save_dir, save_dir, file(exist)).
opt_type(plugin, plugin, atom).               % reported by oro_plugins, not fatal
opt_type(db, db, atom).
opt_type(rebuild_garbage, rebuild_garbage, nonneg).
opt_type(kb_port, kb_port, between(0, 65535)).
opt_type(kb, kb, boolean).
opt_type(config, config, file(read)).
opt_type(log, log, atom).
opt_type(log_payload, log_payload, boolean).
opt_type(debug, debug, atom).
opt_type(idle_timeout, idle_timeout, number).
opt_type(max_connections, max_connections, positive_integer).
opt_type(max_per_address, max_per_address, nonneg).
opt_type(min_reply_latency, min_reply_latency, nonneg).
opt_type(events_before_reply, events_before_reply, boolean).
opt_type(http, http, between(0, 65535)).
opt_type(no_http, http, boolean(false)).
opt_type(http_host, http_host, atom).
opt_type(http_changes, http_changes, boolean).
opt_type(redis, redis, atom).                 % several robots: oro_redis
opt_type(node, node, atom).
opt_type(share, share, atom).
opt_type(follow, follow, atom).
opt_type(share_world, share_world, boolean).

usage("Usage: swipl server/oro_server.pl [option ...]
   or: swipl -g \"use_module(library(oro_server))\" -g oro_server_main -- [option ...]

oro: a knowledge server for cognitive robots, speaking the ORO protocol.

Options:
  --port=N           TCP port to listen on (default 6969; 0 picks a free one)
  --host=ADDR        Address to listen on (default 127.0.0.1, loopback only)
  --ontology=FILE    Load an ontology (.owl/.rdf RDF/XML, .ttl Turtle,
                     .nt N-Triples); repeatable
  --no-commonsense   Do not load the bundled common-sense ontology
  --robot-id=ID      Id of the robot: a synonym of myself
  --time-base=MS     Length of one memory time unit in ms (default 1000)
  --save-dir=DIR     Directory where save may write files (default
                     $XDG_DATA_HOME/oro/saves or ~/.local/share/oro/saves,
                     made on the first save); never the --db directory
                     nor the server's installation
  --plugin=FILE      Load a Prolog plugin declaring extra methods; repeatable
  --db=DIR           Journal the models in DIR (created if needed) and
                     restore them from it on start: nothing acknowledged
                     is lost, even on kill -9
  --rebuild-garbage=N
                     Rebuild the store once rdf_db holds N names (IRIs)
                     more than after the last rebuild, or twice as many,
                     to give back the memory of names no fact uses any
                     more (default 1000000; 0: never)
  --kb-port=N        Also serve the KB-API dialect (knowledge_core, pykb)
                     on port N (default 6971, or a free one with --port=0;
                     0 picks a free one)
  --no-kb            Serve the ORO protocol only
  --config=FILE      Read settings from FILE: terms setting(Name, Value)
                     or setting(Module:Name, Value), one per line
  --log=FILE         Append a line per request to FILE: time, connection,
                     client, method, duration, outcome (SIGHUP reopens it)
  --log-payload      Also log the parameters of each request
  --debug=TOPIC      Print the debug/3 messages of TOPIC, e.g. 'oro(server)';
                     repeatable
  --idle-timeout=S   Close a connection that never registered an event and
                     sent no request for S seconds (default 30; 0: never)
  --max-connections=N
                     Serve at most N connections at once (default 256)
  --max-per-address=N
                     Serve at most N connections from one client address
                     (default 64; 0: no limit)
  --min-reply-latency=MS
                     Send no reply sooner than MS milliseconds after its
                     request was read (default 0: at once); 10 keeps
                     unpatched liboro builds from hanging (README,
                     Clients)
  --events-before-reply
                     Write the events a request fires for the client's
                     own watchers just before its reply (same write)
                     instead of just after: liboro then never loses its
                     connection over them (README, Clients)
  --http=PORT        Serve SPARQL and Pengines over HTTP on PORT
                     (default 6970, or a free one with --port=0;
                     0 picks a free one)
  --no-http          No HTTP side
  --http-host=ADDR   Address of the HTTP side (default 127.0.0.1)
  --http-changes     Let Pengines clients change the store (default: no)
  --redis=URL        Share knowledge with other oro nodes through the Redis
                     server at redis://HOST:PORT (README, Several robots)
  --node=NAME        Name of this node (required with --redis)
  --share=M1,M2      Models whose changes are published (default myself)
  --follow=N1,N2     Nodes whose models are applied here, each to the
                     model named after it; * for every node
  --share-world      Replicate the model world, which every node writes
  -h, --help         Show this help

Settings, each also an option (and a setting(Name, Value) of --config):
").

%!  oro_server_main is det.
%
%   Start the server with the options of the command line
%   (oro_server_arguments/1) and serve until SIGTERM or SIGINT, then
%   halt.

oro_server_main :-
    oro_server_arguments(Argv),
    oro_server_main(Argv).

%!  oro_server_arguments(-Argv) is det.
%
%   Argv are the arguments of the command line meant for the server.
%   When swipl was started with a script (`swipl server/oro_server.pl
%   Arg ...`), they are every argument after the script, taken from
%   the Prolog flag `os_argv`: swipl takes the arguments right after
%   the script whose name ends in `.pl` (`--plugin=x.pl`) for more
%   files to load and removes them from the flag `argv`, so that flag
%   alone would lose them.  A leading `--` is dropped.  Otherwise (as in
%   `swipl -g oro_server_main -- Arg ...`) they are the flag `argv`.

oro_server_arguments(Argv) :-
    (   current_prolog_flag(associated_file, Script),
        current_prolog_flag(os_argv, [_|OsArgv]),
        append(_, [OsScript|Rest], OsArgv),
        script_file(OsScript, Script)
    ->  (   Rest = [--|Argv0]
        ->  true
        ;   Argv0 = Rest
        )
    ;   current_prolog_flag(argv, Argv0)
    ),
    Argv = Argv0.

%   script_file(+OsFile, +Script): the argument OsFile names the file
%   Script, as swipl resolved it for the flag associated_file.

script_file(OsFile, Script) :-
    catch(( prolog_to_os_filename(File, OsFile),
            absolute_file_name(File, Path)
          ), _, fail),
    Path == Script.

%!  oro_server_main(+Argv) is det.
%
%   Start the server with the command-line arguments Argv (see
%   `--help`), in any order, and serve until SIGTERM or SIGINT, then
%   halt: halt(0) after a clean shutdown, halt(1) when an argument or
%   the start is refused, with the reason on stderr.

oro_server_main(Argv) :-
    must_be(list(atomic), Argv),
    (   ( memberchk('--help', Argv) ; memberchk('-h', Argv) )
    ->  usage(Usage),
        oro_cli_settings_help(Settings),
        format("~w~w", [Usage, Settings]),
        halt(0)
    ;   true
    ),
    catch(oro_cli_options(Argv, Positional, Options0), E0,
          ( print_message(error, E0),
            halt(1)
          )),
    command_line_defaults(Options0, Options),
    (   Positional == []
    ->  true
    ;   format(user_error, "oro: unexpected argument(s) ~w (see --help)~n",
               [Positional]),
        halt(1)
    ),
    kb_port_option(Options, Options1),
    (   option(http(_), Options1)
    ->  Options2 = Options1
    ;   option(port(0), Options1)       % a free port: the others too
    ->  Options2 = [http(0)|Options1]
    ;   Options2 = [http(6970)|Options1]
    ),
    catch(( start_log(Options2),
            oro_server_start([silent(false)|Options2], Server)
          ), E,
          ( print_message(error, E),
            halt(1)
          )),
    oro_server_port(Server, Port),
    option(host(Host), Options),
    (   loopback(Host)
    ->  true
    ;   format(user_error, "Warning: listening on ~w: the ORO protocol has no \c
                            authentication; anyone who can reach this address \c
                            can read and change the knowledge base.~n", [Host])
    ),
    on_signal(term, _, shutdown_signal),
    on_signal(int, _, shutdown_signal),
    on_signal(hup, _, reopen_signal),
    threads_settled,
    format("oro listening on ~w:~w~n", [Host, Port]),
    (   oro_server_http_port(Server, HttpPort)
    ->  option(http_host(HttpHost), Options, '127.0.0.1'),
        format("oro web listening on http://~w:~w/~n", [HttpHost, HttpPort])
    ;   true
    ),
    (   oro_server_kb_port(Server, KbPort)
    ->  format("oro serving the KB-API on ~w:~w~n", [Host, KbPort])
    ;   true
    ),
    flush_output,
    load_sparql_engine,
    serve_until_stopped,
    oro_server_shutdown(Server),
    oro_log_close,
    halt(0).

%   command_line_defaults(+Options0, -Options): the options of the
%   command line, with the defaults of those not given taken from the
%   settings (which --config may have set).

command_line_defaults(Options0, Options) :-
    setting(port, Port),
    setting(host, Host),
    setting(rebuild_garbage, Garbage),
    setting(oro_knowledge:robot_id, RobotId),
    setting(oro_save:save_dir, SaveDir),
    setting(oro_memory:time_base, TimeBase),
    merge_options(Options0,
                  [ port(Port), host(Host), rebuild_garbage(Garbage),
                    robot_id(RobotId), save_dir(SaveDir),
                    time_base(TimeBase)
                  ],
                  Options).

start_log(Options) :-
    (   option(log(File), Options)
    ->  option(log_payload(Payload), Options, false),
        oro_log_open(File, [payload(Payload)])
    ;   true
    ).

%   serve_until_stopped: main waits for SIGTERM or SIGINT
%   (shutdown_signal/1), reopening the log on each SIGHUP meanwhile.

serve_until_stopped :-
    thread_get_message(Message),
    (   Message == oro_server_reopen_log
    ->  oro_log_reopen,
        debug(oro(server), 'Log reopened', []),
        serve_until_stopped
    ;   true
    ).

reopen_signal(_Signal) :-
    thread_send_message(main, oro_server_reopen_log).

%   load_sparql_engine: main, idle once the server listens, loads the
%   SPARQL engine (see oro_sparql), so that the first query rarely
%   waits for it.  Should that load fail, the server goes on: each query
%   then gets the error.

load_sparql_engine :-
    catch(oro_sparql_load, Error, print_message(warning, Error)).

%   SIGTERM and SIGINT are handled by the main thread, which waits for
%   this message: the shutdown itself runs outside the signal handler.
%
%   SWI-Prolog blocks SIGINT in every thread but main, not SIGTERM: the
%   kernel may hand a SIGTERM to another thread, whose handler then
%   runs it.  With SWI-Prolog 9.0.4 a thread that has been created but
%   has not run yet drops it.  A supervisor that stops the server right
%   after it said it listens hit that window: on one core, 4 stops in
%   60 were lost (a scratch loop; git log of bench/RESULTS.md).  So main announces
%   that it listens only once every other thread has run a goal it sent
%   it (threads_settled/0): after that, 0 in 90.  A connection is
%   served by a worker made at start (see CONNECTION WORKERS), not by a
%   thread made when the client connects: a SIGTERM sent right after a
%   client connected was lost 8 times in 200 runs of test_durability's
%   sigterm_reply_agrees_with_store when it was, 0 in 200 since.  A
%   thread is still made for a client while spare_workers others are
%   connected, and for an event subscriber's delivery: a SIGTERM that
%   comes just then can still be lost, so a supervisor that sees the
%   server still running should send it again, as the tests do.

shutdown_signal(_Signal) :-
    thread_send_message(main, oro_server_stop).

%   threads_settled: every thread but main and SWI-Prolog's gc thread
%   (which blocks all signals) has run a goal sent by thread_signal/2,
%   so it runs Prolog and takes signals; 5 s at most in all.  A thread
%   that begins to wait on a message queue just as the signal comes
%   notices it only at its next periodic check, 250 ms later (1 start
%   in 20 waited that long for the spare workers): the threads that
%   have not answered within 20 ms are signalled again, which wakes
%   them.  A thread may then answer twice; the answers go to a queue of
%   their own, destroyed at the end, where a late one is dropped.

threads_settled :-
    findall(Thread,
            ( running(Thread),
              \+ memberchk(Thread, [main, gc])
            ),
            Threads),
    message_queue_create(Queue),
    call_cleanup(settle(Threads, Queue, 250),
                 message_queue_destroy(Queue)).

settle([], _, _) :-
    !.
settle(_, _, 0) :-
    !.
settle(Threads0, Queue, Rounds) :-
    include(running, Threads0, Threads),
    forall(member(Thread, Threads),
           catch(thread_signal(Thread, settled(Queue, Thread)), _, true)),
    get_time(Now),
    Deadline is Now + 0.02,
    answered(Queue, Deadline, Threads, Left),
    Rounds1 is Rounds - 1,
    settle(Left, Queue, Rounds1).

running(Thread) :-
    catch(thread_property(Thread, status(running)), _, fail).

settled(Queue, Thread) :-
    catch(thread_send_message(Queue, settled(Thread)), _, true).

%   answered(+Queue, +Deadline, +Threads, -Left): Left are the Threads
%   that did not answer before Deadline.

answered(_, _, [], []) :-
    !.
answered(Queue, Deadline, Threads, Left) :-
    (   thread_get_message(Queue, settled(Thread), [deadline(Deadline)])
    ->  delete(Threads, Thread, Threads1),
        answered(Queue, Deadline, Threads1, Left)
    ;   Left = Threads
    ).

loopback(Host) :-
    memberchk(Host, ['127.0.0.1', localhost, '::1']).

%   kb_port_option(+Options0, -Options): on the command line the KB-API
%   is served on port 6971 (on a free port with --port=0) unless
%   --kb-port says otherwise or --no-kb turns it off.

kb_port_option(Options0, Options) :-
    (   option(kb(false), Options0)
    ->  Options = [kb_port(false)|Options0]
    ;   option(kb_port(_), Options0)
    ->  Options = Options0
    ;   option(port(0), Options0)
    ->  Options = [kb_port(0)|Options0]
    ;   Options = [kb_port(6971)|Options0]
    ).

%!  oro_server_kb_port(+Server, -Port) is semidet.
%
%   The port Server serves the KB-API dialect on; fails if it does not.

oro_server_kb_port(Server, Port) :-
    Server.kbapi \== none,
    oro_kbapi_port(Server.kbapi, Port).

%!  oro_server_start(+Options, -Server) is det.
%
%   Initialise the knowledge base and start listening.  Options are
%   those of the command line: port(Port) (default 6969; 0 picks a
%   free port), host(Host) (default '127.0.0.1'), ontology(File)
%   (repeatable), commonsense(Bool), robot_id(Id), time_base(MS),
%   save_dir(Dir), plugin(File) (repeatable: see oro_plugins; a
%   plugin that cannot be loaded is reported and skipped), db(Dir) (see
%   oro_init/1), rebuild_garbage(N) (default 1,000,000: see
%   oro_store_rebuild/0; every request runs in oro_store_read/1),
%   kb_port(Port) (serve the KB-API dialect too, see oro_kbapi: off
%   unless given, so that servers started here never clash; 0 picks a
%   free port), silent(Bool) (default true; false reports the ontology
%   loads: see oro_init/1), idle_timeout(S), max_connections(N) and
%   max_per_address(N) (set the settings of the same names),
%   min_reply_latency(MS) (default: the setting min_reply_latency, 0;
%   see reply_due/0), events_before_reply(Bool) (default: the setting
%   events_before_reply, false; see oro_reply_with_events/2),
%   http(Port) (default `false`: no HTTP side; 0 picks a free port:
%   see oro_http_start/2), http_host(Host) (default '127.0.0.1'),
%   http_changes(Bool) (default `false`).  Server is an opaque handle.
%
%   @error domain_error(port, Port) if Port is over 65535.

oro_server_start(Options, Server) :-
    must_be(list, Options),
    option(port(Port0), Options, 6969),
    must_be(nonneg, Port0),
    (   Port0 =< 65535
    ->  true
    ;   domain_error(port, Port0)
    ),
    option(host(Host), Options, '127.0.0.1'),
    option(commonsense(CommonSense), Options, true),
    option(robot_id(RobotId), Options, ''),
    option(save_dir(SaveDir), Options, ''),
    option(time_base(TimeBase), Options, 1000),
    option(db(Db), Options, ''),
    option(rebuild_garbage(Garbage), Options, 1000000),
    must_be(nonneg, Garbage),
    option(silent(Silent), Options, true),
    forall(( member(Name, [idle_timeout, max_connections, max_per_address]),
             Option =.. [Name, Value],
             option(Option, Options)
           ),
           set_setting(Name, Value)),
    setting(min_reply_latency, Latency0),
    option(min_reply_latency(Latency), Options, Latency0),
    must_be(nonneg, Latency),
    setting(events_before_reply, EventsFirst0),
    option(events_before_reply(EventsFirst), Options, EventsFirst0),
    must_be(boolean, EventsFirst),
    findall(F, member(ontology(F), Options), Files),
    oro_init([ db(Db),
               silent(Silent),
               commonsense(CommonSense),
               ontologies(Files),
               robot_id(RobotId),
               save_dir(SaveDir),
               time_base(TimeBase)
             ]),
    set_setting(oro_store:rebuild_garbage, Garbage),
    findall(P, member(plugin(P), Options), Plugins),
    oro_load_plugins(Plugins),
    oro_redis_options(Options),
    tcp_socket(Socket),
    tcp_setopt(Socket, reuseaddr),
    (   Port0 =:= 0
    ->  tcp_bind(Socket, Host:Port)
    ;   Port = Port0,
        tcp_bind(Socket, Host:Port)
    ),
    tcp_listen(Socket, 64),
    catch(start_http(Options, Http), E,
          ( tcp_close_socket(Socket),
            throw(E)
          )),
    option(kb_port(KbPort), Options, false),
    catch(start_kbapi(KbPort, Host, KbApi), E2,
          ( (   Http == none
            ->  true
            ;   catch(oro_http_stop(Http), _, true)
            ),
            tcp_close_socket(Socket),
            throw(E2)
          )),
    get_time(Started),
    message_queue_create(Control),
    message_queue_create(Jobs),
    Server = oro_server{socket:Socket, host:Host, port:Port, jobs:Jobs,
                        started:Started, accept:Accept, control:Control,
                        kbapi:KbApi,
                        reply_latency:Latency, events_first:EventsFirst,
                        http:Http},
    start_workers(Server),
    thread_create(accept_loop(Server), Accept, []),
    debug(oro(server), 'Listening on ~w:~w', [Host, Port]).

%   start_kbapi(+Port, +Host, -KbApi): the KB-API listener on Port, or
%   `none` for Port `false`.

start_kbapi(false, _, none) :-
    !.
start_kbapi(Port, Host, KbApi) :-
    oro_kbapi_start([port(Port), host(Host)], KbApi).

%   start_http(+Options, -Http): the HTTP side, or `none`.

start_http(Options, Http) :-
    option(http(HttpPort), Options, false),
    (   HttpPort == false
    ->  Http = none
    ;   option(http_host(HttpHost), Options, '127.0.0.1'),
        option(http_changes(Changes), Options, false),
        oro_http_start([port(HttpPort), host(HttpHost), changes(Changes)],
                       Http)
    ).

%!  oro_server_http_port(+Server, -Port) is semidet.
%
%   The port of the HTTP side of Server; fails if it has none.

oro_server_http_port(Server, Port) :-
    Http = Server.http,
    Http \== none,
    oro_http_port(Http, Port).

%!  oro_server_port(+Server, -Port) is det.
%
%   The port Server listens on.

oro_server_port(Server, Port) :-
    Port = Server.port.

%!  oro_server_connections(+Server, -Count) is det.
%
%   Count is the number of connections Server is serving now.

oro_server_connections(Server, Count) :-
    must_be(dict, Server),
    (   workers(Server.jobs, Busy, _)
    ->  Count = Busy
    ;   Count = 0                           % stopped, and none left
    ).

%   The connections being served, for the stats method.

:- multifile
    oro_methods:server_figure/2.

oro_methods:server_figure(connections, Count) :-
    aggregate_all(count, connection(_), Count).

%   The web inspector's count of connections: those of every server.

:- multifile oro_http_inspector:socket_connections/1.

oro_http_inspector:socket_connections(Count) :-
    aggregate_all(sum(Busy), workers(_, Busy, _), Count).

%!  oro_server_stop(+Server) is det.
%
%   Stop accepting connections and release the listening socket.
%   Connections in progress finish their current request; the workers
%   waiting for a connection end.
%
%   The accept thread is told through the server's control queue and
%   woken by a connection of our own: no asynchronous signal, which
%   could land inside a handler and be taken for an error.

oro_server_stop(Server) :-
    (   Server.kbapi == none
    ->  true
    ;   oro_kbapi_stop(Server.kbapi)
    ),
    (   Server.http == none
    ->  true
    ;   catch(oro_http_stop(Server.http), _, true)
    ),
    thread_send_message(Server.control, stop),
    wake_acceptor(Server),
    thread_join(Server.accept, _),
    catch(tcp_close_socket(Server.socket), _, true),
    message_queue_destroy(Server.control),
    stop_workers(Server).

%!  oro_server_shutdown(+Server) is det.
%
%   Stop the server cleanly: stop accepting, let every request in
%   progress finish and its reply be written (waiting at most
%   `shutdown_grace` seconds for each connection), then close the
%   journals.  Requests that arrive afterwards are not served.  Used on
%   SIGTERM and SIGINT, before halting.

oro_server_shutdown(Server) :-
    oro_server_stop(Server),
    oro_save_cancel,                        % a save can take minutes
    setting(shutdown_grace, Grace),
    findall(Mutex, connection(Mutex), Mutexes),
    include(lock_connection(Grace), Mutexes, Locked),
    oro_redis_stop,
    oro_close,
    length(Mutexes, N),
    length(Locked, Idle),
    debug(oro(server), 'Shut down: ~D of ~D connection(s) finished in time',
          [Idle, N]).

%   Holding a connection's mutex means no request of it is in progress;
%   marking it closed (under the mutex) means none will be served
%   after.  The mutex is released again: the connection's event
%   delivery thread takes it too, and must not block forever (halt/1
%   would wait for it).

lock_connection(Grace, Mutex) :-
    Deadline is Grace * 20,
    lock_connection(Deadline, 0, Mutex).

lock_connection(Max, N, Mutex) :-
    (   catch(mutex_trylock(Mutex), _, fail)
    ->  assertz(closed_connection(Mutex)),
        mutex_unlock(Mutex)
    ;   \+ connection(Mutex)              % it ended meanwhile
    ->  true
    ;   N < Max
    ->  sleep(0.05),
        N1 is N + 1,
        lock_connection(Max, N1, Mutex)
    ;   fail
    ).

wake_acceptor(Server) :-
    (   memberchk(Server.host, ['0.0.0.0', '::', ''])
    ->  Host = '127.0.0.1'
    ;   Host = Server.host
    ),
    catch(setup_call_cleanup(tcp_connect(Host:Server.port, Stream, []),
                             true,
                             close(Stream, [force(true)])),
          E,
          ( print_message(warning, E),
            thread_signal(Server.accept, throw(oro_stop))
          )).

accept_loop(Server) :-
    catch(accept_connections(Server), oro_stop, true).

accept_connections(Server) :-
    repeat,
    tcp_accept(Server.socket, Client, Peer),
    (   thread_peek_message(Server.control, stop)
    ->  !,
        tcp_close_socket(Client)
    ;   start_connection(Server, Client, Peer),
        fail
    ).

%   refuse_connection(+Client, +Peer, +Why): tell the client why it
%   is not served (all workers busy, too many connections from its
%   address, or no thread for it), and close it.

refuse_connection(Client, Peer, Why) :-
    (   Why = full(Max)
    ->  print_message(warning,
                      format("oro: connection from ~p refused: ~D connections \c
                              open already (max_connections)", [Peer, Max]))
    ;   Why = address(PerMax)
    ->  print_message(warning,
                      format("oro: connection from ~p refused: ~D connections \c
                              from that address already (max_per_address)",
                             [Peer, PerMax]))
    ;   print_message(warning, Why)
    ),
    catch(setup_call_cleanup(
              tcp_open_socket(Client, Pair),
              ( stream_pair(Pair, _, Out),
                set_stream(Out, encoding(utf8)),
                oro_write_error(Out,
                                "laas.openrobots.ontology.exceptions.OntologyServerException",
                                "Too many connections: try again later.")
              ),
              close(Pair, [force(true)])),
          error(_, _), true).

                 /*******************************
                 *      CONNECTION WORKERS      *
                 *******************************/

%   A connection is served by a worker thread, which then waits on the
%   server's job queue for the next one.  `spare_workers` of them are
%   made at start, before the server says it listens, and as many are
%   kept waiting when connections end; more are made when every one is
%   busy, up to `max_connections` in all.  So a client that connects
%   usually finds a thread ready: connecting does not pay for making
%   one, and no thread is being made when the server is sent SIGTERM
%   (SWI-Prolog 9.0.4 drops a signal the kernel hands to a thread
%   being made: see shutdown_signal/1).
%
%   workers(Jobs, Busy, Idle), under the mutex oro_server_workers: the
%   number of connections being served and of workers waiting on the
%   queue Jobs.  Only the accept thread hands out connections, so a
%   connection it counts as given to a waiting worker always finds one.

start_workers(Server) :-
    setting(max_connections, Max),
    setting(spare_workers, Spare0),
    Spare is min(Spare0, Max),
    Jobs = Server.jobs,
    with_mutex(oro_server_workers, assertz(workers(Jobs, 0, Spare))),
    forall(between(1, Spare, _),
           thread_create(connection_worker(Server, 1), _, [detached(true)])).

%   start_connection(+Server, +Client, +Peer): give the connection to
%   a waiting worker, or to a new one, or refuse it.

start_connection(Server, Client, Peer) :-
    setting(max_connections, Max),
    Jobs = Server.jobs,
    peer_host(Peer, Host),
    with_mutex(oro_server_workers, reserve_connection(Jobs, Max, Host, How)),
    (   How == waiting
    ->  thread_send_message(Jobs, serve(Client, Peer))
    ;   How == new
    ->  catch(thread_create(connection_worker(Server, 1, Client, Peer), _,
                            [detached(true)]),
              Error,
              ( with_mutex(oro_server_workers,
                           ( unreserve_worker(Jobs),
                             address_released(Jobs, Host)
                           )),
                refuse_connection(Client, Peer, Error)
              ))
    ;   refuse_connection(Client, Peer, How)
    ).

%   reserve_connection(+Jobs, +Max, +Host, -How): as reserve_worker/3,
%   but How is address(PerMax) when Host has `max_per_address`
%   connections already.
%
%   from_address(Jobs, Host, Count): Count connections from Host are
%   counted (from acceptance to release) by the workers of Jobs.  A
%   per-address cap keeps one client from taking every connection: the
%   others, from other addresses, are still served (idle connections
%   are closed after idle_timeout, which serves the rest).

reserve_connection(Jobs, Max, Host, How) :-
    setting(max_per_address, PerMax),
    (   PerMax > 0,
        from_address(Jobs, Host, Count),
        Count >= PerMax
    ->  How = address(PerMax)
    ;   reserve_worker(Jobs, Max, How0),
        (   How0 == full
        ->  How = full(Max)
        ;   How = How0,
            address_added(Jobs, Host)
        )
    ).

address_added(Jobs, Host) :-
    (   retract(from_address(Jobs, Host, Count0))
    ->  Count is Count0 + 1
    ;   Count = 1
    ),
    assertz(from_address(Jobs, Host, Count)).

address_released(Jobs, Host) :-
    (   retract(from_address(Jobs, Host, Count0)),
        Count0 > 1
    ->  Count is Count0 - 1,
        assertz(from_address(Jobs, Host, Count))
    ;   true
    ).

peer_host(Peer, Host) :-
    (   Peer = Host0:_
    ->  Host = Host0
    ;   Host = Peer
    ).

%   release_connection(+Jobs, +Peer, -Wait): release_worker/2 for a
%   connection from Peer.

release_connection(Jobs, Peer, Wait) :-
    peer_host(Peer, Host),
    address_released(Jobs, Host),
    release_worker(Jobs, Wait).

%   reserve_worker(+Jobs, +Max, -How): count one more connection, for a
%   worker that waits (How = waiting) or a new one (new), unless Max
%   are served already (full).

reserve_worker(Jobs, Max, How) :-
    workers(Jobs, Busy, Idle),
    (   ( Busy >= Max ; Idle == stopped )
    ->  How = full
    ;   Busy1 is Busy + 1,
        (   Idle > 0
        ->  How = waiting,
            Idle1 is Idle - 1
        ;   How = new,
            Idle1 = Idle
        ),
        retract(workers(Jobs, Busy, Idle)),
        assertz(workers(Jobs, Busy1, Idle1))
    ).

%   unreserve_worker(+Jobs): count one connection less, for which no
%   worker could be made.

unreserve_worker(Jobs) :-
    retract(workers(Jobs, Busy, Idle)),
    Busy1 is Busy - 1,
    assertz(workers(Jobs, Busy1, Idle)).

%   release_worker(+Jobs, -Wait): count one connection less; Wait is
%   true if its worker is to wait for another one (fewer than
%   spare_workers wait), false if it is to end, as it is once the server
%   has stopped (Idle is then `stopped`, and the count is dropped with
%   the last connection).

release_worker(Jobs, Wait) :-
    retract(workers(Jobs, Busy, Idle)),
    Busy1 is Busy - 1,
    setting(spare_workers, Spare),
    (   Idle == stopped
    ->  Wait = false,
        (   Busy1 =:= 0
        ->  true
        ;   assertz(workers(Jobs, Busy1, stopped))
        )
    ;   Idle < Spare
    ->  Wait = true,
        Idle1 is Idle + 1,
        assertz(workers(Jobs, Busy1, Idle1))
    ;   Wait = false,
        assertz(workers(Jobs, Busy1, Idle))
    ).

%   connection_worker(+Server, +Serial[, +Client, +Peer]): serve
%   connections until the server stops or enough workers wait.  Serial
%   numbers the connections the thread serves, so that a signal meant
%   to end one of them does not end a later one (see end_connection/3).
%   The queue is destroyed when the server stops: a worker waiting on
%   it, or coming back to it, ends.

connection_worker(Server, Serial) :-
    (   catch(thread_get_message(Server.jobs, serve(Client, Peer)),
              error(existence_error(message_queue, _), _),
              fail)
    ->  connection_worker(Server, Serial, Client, Peer)
    ;   true
    ).

connection_worker(Server, Serial, Client, Peer) :-
    catch(serve_job(Server, Serial, Client, Peer),
          oro_connection_end(_),            % a signal that came just after
          true),
    with_mutex(oro_server_workers, release_connection(Server.jobs, Peer, Wait)),
    (   Wait == true
    ->  Next is Serial + 1,
        connection_worker(Server, Next)
    ;   true
    ).

serve_job(Server, Serial, Client, Peer) :-
    nb_setval(oro_server_serving, Serial),
    catch(serve_connection(Server, Serial, Client, Peer), Error,
          connection_failed(Error)),
    nb_setval(oro_server_serving, none),
    release_stacks.

%   release_stacks: a worker whose stacks grew past 4 MB (a large
%   request) gives them back before it waits.  Trimming small ones
%   would slow every connection for nothing (git log of bench/RESULTS.md).

release_stacks :-
    statistics(global, Global),
    statistics(local, Local),
    statistics(trail, Trail),
    (   Global + Local + Trail > 4 194 304
    ->  garbage_collect,
        trim_stacks
    ;   true
    ).

connection_failed(Error) :-
    (   Error = oro_connection_end(_)
    ->  true
    ;   print_message(warning, Error)
    ).

%   end_connection(+Thread, +Serial, +Why): end the connection Serial
%   of the worker Thread, if it is still serving it (oro_methods calls
%   this through the connection's context, from the thread delivering
%   its events).  The signal throws once: a later one finds the worker
%   no longer serving Serial, even while it is still ending it.

end_connection(Thread, Serial, Why) :-
    catch(thread_signal(Thread, end_serving(Serial, Why)), _, true).

end_serving(Serial, Why) :-
    (   nb_current(oro_server_serving, Serial)
    ->  nb_setval(oro_server_serving, none),
        throw(oro_connection_end(Why))
    ;   true
    ).

%   stop_workers(+Server): the waiting workers end; connections already
%   given to a worker but not taken yet are closed.

stop_workers(Server) :-
    Jobs = Server.jobs,
    with_mutex(oro_server_workers, workers_stopped(Jobs)),
    forall(thread_get_message(Jobs, serve(Client, Peer), [timeout(0)]),
           ( catch(tcp_close_socket(Client), _, true),
             with_mutex(oro_server_workers, release_connection(Jobs, Peer, _))
           )),
    message_queue_destroy(Jobs).

workers_stopped(Jobs) :-
    retract(workers(Jobs, Busy, _)),
    (   Busy =:= 0
    ->  true
    ;   assertz(workers(Jobs, Busy, stopped))
    ).

serve_connection(Server, Serial, Client, Peer) :-
    setup_call_cleanup(
        tcp_open_socket(Client, Pair),
        ( tcp_setopt(Client, nodelay),      % events right after replies
          serve_stream(Server, Serial, Pair, Peer)
        ),
        close(Pair, [force(true)])).

%   The connection's context: its streams, the mutex every write to it
%   holds (replies and pushed events never interleave, and a reply is
%   written in one write with the events its request caused: see
%   oro_methods, CONNECTION EVENTS), a slot for its event subscriber
%   (oro_methods creates it on first registration; it is destroyed with
%   the connection), and the server's reply latency and event order.

serve_stream(Server, Serial, Pair, Peer) :-
    stream_pair(Pair, In, Out),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)),
    setting(write_timeout, WriteTimeout),
    set_stream(Out, timeout(WriteTimeout)),
    setting(idle_timeout, Idle),
    (   Idle > 0
    ->  set_stream(In, timeout(Idle))
    ;   true
    ),
    debug(oro(server), 'Connection from ~q', [Peer]),
    setting(max_request_size, Limit),
    setting(max_params, MaxParams),
    thread_self(Me),
    End = oro_server:end_connection(Me, Serial),
    setup_call_cleanup(
        ( mutex_create(Mutex),
          with_mutex(oro_connections, assertz(connection(Mutex)))
        ),
        ( flag(oro_server_connection, Id0, Id0 + 1),
          Id is Id0 + 1,
          Context = _{started:Server.started, peer:Peer, in:In, out:Out,
                      id:Id,
                      mutex:Mutex, end:End,
                      subscribers:slot([]),
                      max_params:MaxParams,
                      reply_latency:Server.reply_latency,
                      events_first:Server.events_first},
          MaxLines is MaxParams + 1024,     % the method, #end#, blank lines
          catch(( oro_reader(In, Reader, [ max_request_size(Limit),
                                           max_lines(MaxLines)
                                         ]),
                  serve_requests(Context, Reader, Out)
                ), Error,
                connection_ended(Context, Error)),
          oro_connection_closed(Context)
        ),
        ( with_mutex(oro_connections,
                     ( retractall(connection(Mutex)),
                       retractall(closed_connection(Mutex))
                     )),
          catch(mutex_destroy(Mutex), _, true)    % held by a shutdown
        )).

%   A connection silent for longer than idle_timeout (holding no event
%   subscriber, see read_request/5) is told why it is closed; other
%   errors (the peer left, a reply it would not read
%   within write_timeout) just end it.

connection_ended(Context, error(timeout_error(read, _), _)) :-
    !,
    setting(idle_timeout, Idle),
    format(string(Message), "No request for ~w s: closing the connection.",
           [Idle]),
    debug(oro(server), 'Connection ~q idle: closing', [Context.peer]),
    catch(with_mutex(Context.mutex,
                     oro_write_error(Context.out,
                                     "laas.openrobots.ontology.exceptions.OntologyServerException",
                                     Message)),
          _, true).
connection_ended(Context, Error) :-
    debug(oro(server), 'Connection ~q ended: ~q', [Context.peer, Error]).

serve_requests(Context, Reader, Out) :-
    Ahead = ahead(none),
    setup_call_catcher_cleanup(true,
                               serve_requests(Context, Reader, Out, Ahead),
                               Catcher,
                               stop_ahead(Ahead, Catcher)).

serve_requests(Context, Reader0, Out, Ahead) :-
    read_request(Context, Ahead, Reader0, Request, Reader),
    request_read(Context.reply_latency),
    (   serve_request(Request, Context, Out, Reader, Ahead)
    ->  serve_requests(Context, Reader, Out, Ahead)
    ;   true
    ).

%   read_request(+Context, +Ahead, +Reader0, -Request, -Reader): the
%   next request.  The input's timeout is idle_timeout: a connection
%   that sends nothing for that long is closed (connection_ended/2),
%   unless it holds an event subscriber (a client waiting for its
%   events sends nothing) or the helper is still answering its
%   requests: then the read starts again, if the one that timed out
%   consumed no byte (byte_count/2), else the connection is closed as
%   the request begun is lost.

read_request(Context, Ahead, Reader0, Request, Reader) :-
    In = Context.in,
    byte_count(In, Before),
    catch(oro_read_request(Reader0, Request0, Reader1), Error, true),
    (   var(Error)
    ->  Request = Request0,
        Reader = Reader1
    ;   Error = error(timeout_error(read, _), _),
        (   arg(1, Context.subscribers, [_|_])
        ->  true
        ;   ahead_busy(Ahead)
        ),
        byte_count(In, Before)
    ->  debug(oro(server), 'Connection ~q silent but subscribed: kept',
              [Context.peer]),
        read_request(Context, Ahead, Reader0, Request, Reader)
    ;   throw(Error)
    ).

%   serve_request(+Request, +Context, +Out, +Reader, +Ahead) is semidet:
%   answer Request, here or ahead (see REQUESTS AHEAD); fails when the
%   connection must end.

serve_request(Request, Context, Out, Reader, Ahead) :-
    (   ahead_request(Request, Context, Reader, Ahead, Prepared),
        have_helper(Context, Ahead)
    ->  send_ahead(Ahead, Prepared)
    ;   ahead_drained(Ahead),
        handle_request(Request, Context, Out)
    ).

%   dispatched_request(+Request, +Context): Request goes to the
%   dispatcher (handle_request/3's last clause): it is neither `close`
%   nor over the connection's max_params.

dispatched_request(request(Method, Params), Context) :-
    length(Params, N),
    N =< Context.max_params,
    \+ string_lower(Method, "close").

%   handle_request(+Request, +Context, +Out) is semidet: fails when the
%   connection must end.

handle_request(end_of_file, _, _) :-
    !,
    fail.
handle_request(help, Context, Out) :-
    !,
    handle_request(request("help", []), Context, Out).
handle_request(bad(too_large(Limit)), Context, Out) :-
    !,
    format(string(Message), "Request larger than ~d bytes: closing the \c
           connection.", [Limit]),
    with_mutex(Context.mutex,
               oro_write_error(Out, "laas.openrobots.ontology.exceptions.OntologyServerException",
                               Message)),
    Drain is 4 * Limit,
    oro_drain_input(Context.in, Drain, 2),
    fail.
handle_request(bad(too_many_lines(Max)), Context, Out) :-
    !,
    format(string(Message), "Too many parameters: the request has more \c
           than ~D lines (at most ~D parameters).",
           [Max, Context.max_params]),
    with_mutex(Context.mutex,
               oro_write_error(Out, "laas.openrobots.ontology.exceptions.OntologyServerException",
                               Message)).
handle_request(bad(encoding), Context, Out) :-
    !,
    reply_due,
    with_mutex(Context.mutex,
               oro_write_error(Out, "laas.openrobots.ontology.exceptions.OntologyServerException",
                               "The request is not valid UTF-8.")).
handle_request(request(_, Params), Context, Out) :-
    length(Params, N),
    Max = Context.max_params,
    N > Max,
    !,
    format(string(Message), "Too many parameters: ~D (at most ~D).", [N, Max]),
    reply_due,
    with_mutex(Context.mutex,
               oro_write_error(Out, "laas.openrobots.ontology.exceptions.OntologyServerException",
                               Message)).
handle_request(request(Method, _), Context, Out) :-
    string_lower(Method, "close"),
    !,
    with_mutex(Context.mutex, oro_write_closing(Out)),
    fail.
handle_request(request(Method, Params), Context, Out) :-
    answer(Context, request(Method, Params), Out).

%   answer(+Context, +Prepared, +Out) is semidet: perform the request
%   (oro_perform/3) and write its reply, holding the connection's mutex;
%   fail if the server is shutting down.

answer(Context, Prepared, Out) :-
    Mutex = Context.mutex,
    with_mutex(Mutex, answer(Mutex, Context, Prepared, Out)).

%   (A named predicate, as a meta-called if-then-else would be compiled
%   again on every request.)

answer(Mutex, Context, Prepared, Out) :-
    \+ closed_connection(Mutex),
    get_time(Start),
    oro_store_read(oro_perform(Context, Prepared, Reply)),
    get_time(End),
    Seconds is End - Start,
    oro_log_request(Context.id, Context.peer, Prepared, Seconds, Reply),
    reply_due,
    (   oro_reply_with_events(Context, write_reply(Reply))
    ->  true
    ;   write_reply(Reply, Out)
    ).

%   MINIMUM REPLY LATENCY
%
%   liboro up to 1.3.1 notes that it waits for a reply only after it has
%   written the request: a reply read before that is taken for an
%   unexpected message and dropped, and the call waits for ever (see
%   README, Clients).  oro-server 0.8.2 answered slowly enough for the
%   window not to matter; oro answers in 0.1-0.5 ms.  With the setting
%   min_reply_latency at L > 0, the worker notes when it read each
%   request (request_read/1) and a reply waits until L ms after that
%   (reply_due/0), so a request that takes longer is not delayed more.
%   The note is a global variable of the worker thread; requests
%   answered ahead by a connection's helper (pipelined, see REQUESTS
%   AHEAD) are not delayed: liboro never pipelines.

request_read(Latency) :-
    reply_due_time(Latency, Due),
    (   Due == none
    ->  true
    ;   nb_setval(oro_reply_due, Due)
    ).

%   reply_due_time(+Latency, -Due): the time (get_time/1) a reply to a
%   request read now is due, or `none` for a latency of 0.

reply_due_time(0, none) :-
    !.
reply_due_time(Latency, Due) :-
    get_time(Now),
    Due is Now + Latency / 1000.

reply_due :-
    (   nb_current(oro_reply_due, Due),
        Due \== none
    ->  nb_setval(oro_reply_due, none),
        get_time(Now),
        Wait is Due - Now,
        (   Wait > 0
        ->  sleep(Wait)
        ;   true
        )
    ;   true
    ).

write_reply(ok(Value), Out) :-
    oro_write_ok(Out, Value).
write_reply(error(Name, Message), Out) :-
    oro_write_error(Out, Name, Message).

                 /*******************************
                 *        REQUESTS AHEAD        *
                 *******************************/

%   A client may send its next request before it has read the reply to
%   the previous one (ORO-SPEC lets it pipeline).  A connection's worker
%   then prepares the next request (oro_prepare/3: finding the method,
%   decoding its parameters, parsing the statements it adds) while a
%   helper thread of the connection answers the previous one: a client
%   streaming large batches has them parsed on one core while they are
%   stored on the other.
%
%   A request goes ahead, to the helper, when the helper still has
%   requests to answer (replies keep the order of the requests), or when
%   it is large (ahead_min_bytes/1) and the next one is already there;
%   any other is answered by the worker itself, once the helper has
%   answered all it was given.  Only methods that do not use the
%   connection's context go ahead: the helper has a copy of the context,
%   and the subscribers an events method makes must be the worker's.
%   Once the connection has registered an event, no request goes ahead:
%   its replies carry the events they fire (oro_reply_with_events/2),
%   which the worker's context knows how to take.
%   At most ahead_max/1 requests wait for the helper, so a client
%   cannot make the server read its requests ahead without bound.
%
%   Ahead is ahead(none), or ahead(helper(Thread, Jobs, Done, Given))
%   once the helper is made: Given requests were sent to the queue Jobs
%   and not yet answered, as the helper tells on the queue Done (`done`,
%   or ended(Why) when the connection must end: the helper then stops).

ahead_min_bytes(1024).
ahead_max(2).

ahead_request(Request, Context, Reader, Ahead, Prepared) :-
    Request = request(Method, Params),
    (   ahead_busy(Ahead)
    ->  true
    ;   ahead_min_bytes(Min),
        large_params(Params, 0, Min),
        oro_reader_pending(Reader)
    ),
    dispatched_request(Request, Context),
    \+ oro_connection_events(Context),
    oro_prepare(Method, Params, Prepared),
    Prepared = prepared(Impl, _, _),
    \+ uses_context(Impl).

large_params([Param|Params], Size0, Min) :-
    string_length(Param, Length),
    Size is Size0 + Length,
    (   Size >= Min
    ->  true
    ;   large_params(Params, Size, Min)
    ).

uses_context(context(_)).
uses_context(transaction(Impl)) :-
    uses_context(Impl).

%   have_helper(+Context, +Ahead): the connection has its helper,
%   made now if needed; fails if it cannot be made (the request is then
%   answered in turn).

have_helper(_, Ahead) :-
    Ahead = ahead(helper(_, _, _, _)),
    !.
have_helper(Context, Ahead) :-
    message_queue_create(Jobs),
    message_queue_create(Done),
    (   catch(thread_create(ahead_helper(Context, Jobs, Done), Thread, []),
              Error,
              ( print_message(warning, Error),
                fail
              ))
    ->  debug(oro(server), 'Connection ~q: requests ahead', [Context.peer]),
        nb_setarg(1, Ahead, helper(Thread, Jobs, Done, 0))
    ;   message_queue_destroy(Jobs),
        message_queue_destroy(Done),
        fail
    ).

%   send_ahead(+Ahead, +Prepared): give Prepared to the helper once
%   fewer than ahead_max/1 wait.

send_ahead(Ahead, Prepared) :-
    ahead_max(Max),
    ahead_wait(Ahead, Max),
    Ahead = ahead(Helper),
    Helper = helper(_, Jobs, _, Given),
    thread_send_message(Jobs, answer(Prepared)),
    Given1 is Given + 1,
    nb_setarg(4, Helper, Given1).

%   ahead_busy(+Ahead): the helper has requests to answer, once what
%   it has told is taken.

ahead_busy(Ahead) :-
    Ahead = ahead(helper(_, _, _, _)),
    take_told(Ahead),
    Ahead = ahead(helper(_, _, _, Given)),
    Given > 0.

take_told(Ahead) :-
    Ahead = ahead(helper(_, _, Done, _)),
    (   thread_peek_message(Done, _)
    ->  ahead_collect(Ahead),
        take_told(Ahead)
    ;   true
    ).

%   ahead_drained(+Ahead): wait until the helper has answered every
%   request it was given.

ahead_drained(Ahead) :-
    ahead_wait(Ahead, 1).

%   ahead_wait(+Ahead, +Max): wait until fewer than Max requests are
%   given to the helper and not answered.

ahead_wait(Ahead, Max) :-
    (   Ahead = ahead(helper(_, _, _, Given)),
        Given >= Max
    ->  ahead_collect(Ahead),
        ahead_wait(Ahead, Max)
    ;   true
    ).

%   ahead_collect(+Ahead): take the helper's next message, waiting for
%   it; throws oro_ahead_ended(Why) if the helper stopped and the
%   connection must end.

ahead_collect(Ahead) :-
    Ahead = ahead(Helper),
    Helper = helper(_, _, Done, Given),
    thread_get_message(Done, Message),
    (   Message == done
    ->  Given1 is Given - 1,
        nb_setarg(4, Helper, Given1)
    ;   Message = ended(Why),
        throw(oro_ahead_ended(Why))
    ).

%   ahead_helper(+Context, +Jobs, +Done): answer the requests sent on
%   Jobs, in order, until `stop`, until the connection must end, or
%   until the worker signals oro_ahead_stop.

ahead_helper(Context, Jobs, Done) :-
    catch(help_ahead(Context, Jobs, Done), oro_ahead_stop, true).

help_ahead(Context, Jobs, Done) :-
    thread_get_message(Jobs, Job),
    (   Job = answer(Prepared)
    ->  (   catch(answer(Context, Prepared, Context.out), Error, true)
        ->  (   var(Error)
            ->  thread_send_message(Done, done),
                help_ahead(Context, Jobs, Done)
            ;   thread_send_message(Done, ended(Error))
            )
        ;   thread_send_message(Done, ended(closed))
        )
    ;   true
    ).

%   stop_ahead(+Ahead, +Catcher): stop the helper, if any.  When the
%   connection ends normally (Catcher is exit or fail) the helper has
%   answered every request already; when it ends on an exception (the
%   peer left, its events overflowed...), the helper is interrupted,
%   as the worker would have been, and what it was not done with is
%   not answered.

stop_ahead(ahead(none), _) :-
    !.
stop_ahead(ahead(helper(Thread, Jobs, Done, _)), Catcher) :-
    (   normal_end(Catcher)
    ->  true
    ;   catch(thread_signal(Thread, throw(oro_ahead_stop)), _, true)
    ),
    thread_send_message(Jobs, stop),
    thread_join(Thread, _),
    message_queue_destroy(Jobs),
    message_queue_destroy(Done).

normal_end(exit).
normal_end(fail).
