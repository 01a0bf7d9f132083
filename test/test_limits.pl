:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).

/*  Tests for the server's limits (issue #8): the number of parameters
    of a request, the idle timeout and the write timeout.  Each limit
    is lowered with set_setting/2 for the test and restored after.
    (The request size limit is covered by test_protocol_framing.)

    Run: cd /work/main && swipl -g run_tests -t halt test/test_limits.pl
*/

:- use_module(library(settings)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(socket)).
:- use_module(library(yall)).
:- use_module(library(oro), [oro_init/1]).
:- use_module('../server/oro_server',
              [oro_server_start/2, oro_server_port/2, oro_server_shutdown/1]).

%   limits_with(+Setting, +Value, :Goal): run Goal with the server
%   setting oro_server:Setting at Value.

:- meta_predicate limits_with(+, +, 0).

limits_with(Setting, Value, Goal) :-
    setting(oro_server:Setting, Old),
    setup_call_cleanup(set_setting(oro_server:Setting, Value),
                       Goal,
                       set_setting(oro_server:Setting, Old)).

%   limits_params(+N, -Params): N statement parameters for a
%   hypothetical method, each well formed.

limits_params(N, Params) :-
    numlist(1, N, Ns),
    maplist([I, P]>>format(string(P), "[limits_~d rdf:type Thing]", [I]),
            Ns, Params).

:- begin_tests(limits_params,
               [ setup(test_server_start([])),
                 cleanup(test_server_stop)
               ]).

test(too_many, [true(Name-Still == "laas.openrobots.ontology.exceptions.OntologyServerException"-ok("true"))]) :-
    limits_with(max_params, 8,
                ( limits_params(9, Params),
                  test_call(add, Params, Reply),
                  test_error_name(Reply, Name),
                  test_call(check, ["[myself rdf:type Robot]"], Still)
                )).

test(at_the_limit_is_served, [true(Reply == ok(""))]) :-
    limits_with(max_params, 8,
                test_call(add, ["[limits_a rdf:type Thing]"], Reply)).

test(rejected_request_changes_nothing, [true(Reply == ok("false"))]) :-
    limits_with(max_params, 2,
                ( test_call(add, ["[limits_b rdf:type Thing]", "longterm", "x"], _),
                  test_call(check, ["[limits_b rdf:type Thing]"], Reply)
                )).

:- end_tests(limits_params).

:- begin_tests(limits_timeouts,
               [ setup(test_server_start([])),
                 cleanup(test_server_stop)
               ]).

%   A connection that stays silent is told why and closed; a connection
%   opened afterwards is served as usual.

test(idle_connection_closed, [true(Messages-Reply == [error, end_of_file]-ok("true"))]) :-
    test_server_port(Port),
    limits_with(idle_timeout, 0.2,
                ( oro_connect(Port, Conn),
                  call_cleanup(( oro_receive(Conn, M1, 10),
                                 oro_receive(Conn, M2, 10)
                               ),
                               oro_disconnect(Conn))
                )),
    functor(M1, F1, _),
    Messages = [F1, M2],
    test_call(check, ["[myself rdf:type Robot]"], Reply).

%   Under the default idle timeout (30 s), a connection silent for
%   0.5 s is kept.

test(idle_timeout_by_default, [true(Reply == ok("true"))]) :-
    setting(oro_server:idle_timeout, 30),
    test_server_port(Port),
    oro_connect(Port, Conn),
    call_cleanup(( oro_receive(Conn, Nothing, 0.5),
                   assertion(Nothing == timeout),
                   oro_call(Conn, check, ["[myself rdf:type Robot]"], Reply)
                 ),
                 oro_disconnect(Conn)).

%   A client that sends requests and never reads its replies is
%   disconnected after write_timeout; others are served meanwhile.

test(client_that_never_reads, [true(Served-Gone == ok("true")-true)]) :-
    test_server_port(Port),
    limits_with(write_timeout, 1,
                ( tcp_connect('127.0.0.1':Port, Pair, []),
                  stream_pair(Pair, _In, Out),
                  set_stream(Out, timeout(30)),
                  call_cleanup(limits_flood(Out, Gone),
                               close(Pair, [force(true)])),
                  test_call(check, ["[myself rdf:type Robot]"], Served)
                )).

%   Send `find` requests with long answers until the server stops
%   reading us (its write blocked, then timed out and closed): a write
%   error, or 200 MB sent.  Bounded either way.

limits_flood(Out, Gone) :-
    format(string(Request), "listMethods~n#end#~n", []),
    catch(( between(1, 2000000, _),
            format(Out, "~s", [Request]),
            flush_output(Out),
            fail
          ; Gone = false
          ),
          error(_, _),
          Gone = true).

:- end_tests(limits_timeouts).


                 /*******************************
                 *          SHUTDOWN            *
                 *******************************/

%   oro_server_shutdown/1 (what SIGTERM and SIGINT run) in this process:
%   once it returns, the connections' mutexes are free -- a connection
%   whose event delivery thread waits for its mutex must be able to end,
%   or halt/1 waits for it forever -- and a connection left open is not
%   served any more: its next request closes it.  "Free" is waited for
%   (bounded): a delivery thread may hold a mutex for the instant of a
%   write, and the test waits for A's event so none is due then.

limits_mutex_free(Mutex) :-
    thread_create(( mutex_trylock(Mutex)
                  ->  mutex_unlock(Mutex)
                  ;   fail
                  ),
                  T, []),
    thread_join(T, Status),
    Status == true.

limits_connection_mutexes(Mutexes) :-
    findall(M, oro_server:connection(M), Mutexes).

:- begin_tests(limits_shutdown).

test(connections_released_and_closed,
     [ true(Got == [2, true, ok("")]-end_of_file) ]) :-
    test_server_stop,
    test_fixture('testsuite.ttl', File),
    oro_server_start([ port(0), host('127.0.0.1'), commonsense(false),
                       ontology(File)
                     ], Server),
    oro_server_port(Server, Port),
    oro_connect(Port, A),
    oro_connect(Port, B),
    call_cleanup(
        ( oro_call(A, registerEvent,
                   ["NEW_INSTANCE", "ON_TRUE", "x", "[?x rdf:type Monkey]"],
                   ok(_)),
          oro_call(B, add, ["[kong rdf:type Monkey]"], Added),
          oro_next_event(A, event(_, _), 10),
          test_wait_until(( limits_connection_mutexes(Ms0),
                            length(Ms0, 2)
                          ), 10),
          oro_server_shutdown(Server),
          limits_connection_mutexes(Ms),
          length(Ms, N),
          test_bool(test_wait_until(maplist(limits_mutex_free, Ms), 10),
                    Free),
          oro_send(B, check, ["[kong rdf:type Monkey]"]),
          oro_drain(B, Replies, 10),
          (   memberchk(end_of_file, Replies)
          ->  After = end_of_file
          ;   After = Replies
          ),
          Got = [N, Free, Added]-After
        ),
        ( oro_disconnect(A),
          oro_disconnect(B),
          oro_init([])
        )).

:- end_tests(limits_shutdown).
