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

%   With the idle timeout off (the default), a connection is kept.

test(no_idle_timeout_by_default, [true(Reply == ok("true"))]) :-
    setting(oro_server:idle_timeout, 0),
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
