:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module(library(aggregate)).
:- use_module('../server/oro_server').
:- use_module(library(oro/server/oro_methods)).
:- use_module(library(oro)).
:- use_module(library(oro/parse/oro_parse)).

/*  Requests answered ahead (server/oro_server.pl, REQUESTS AHEAD): a
    client that sends its requests back to back has the next one
    prepared (oro_methods:oro_prepare/3) while a helper thread of its
    connection answers the previous one.

    ahead_prepare checks, in process, that a prepared request is
    answered as the dispatcher answers it; ahead_server drives a real
    server over a socket with pipelined batches and checks the replies,
    their order and the store.  Whether a connection used its helper is
    seen through the server's debug message on oro(server)
    (prolog:debug_print_hook/3, which also keeps such messages quiet).

    Run: swipl -g run_tests -t halt test/test_ahead.pl
*/

:- dynamic
    ahead_used/1.                       % Peer

                 /*******************************
                 *           PREPARED           *
                 *******************************/

:- begin_tests(ahead_prepare,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

%   Each request, prepared then performed, gets the reply the
%   dispatcher gives; the store is reset before each of the two.

test(prepared_as_dispatched, true(Differ == [])) :-
    findall(M-Ps, prepare_case(M, Ps), Cases),
    include(differs, Cases, Differ).
test(statements_parsed_ahead, true(Atoms == true)) :-
    oro_prepare("add", ["[\"ahead1 isOn table1\"]"], prepared(_, add, Args)),
    (   Args = [[rdf(S, P, O)]],
        maplist(atom, [S, P, O])
    ->  Atoms = true
    ;   Atoms = Args
    ).
test(statements_parsed_ahead_any_case, true(Name-Args = add-[[rdf(_, _, _)]])) :-
    oro_prepare("ADD", ["[\"ahead1 isOn table1\"]"], prepared(_, Name, Args)).
test(agent_statements_parsed_ahead, true(Args = ["human1", [rdf(_, _, _)]])) :-
    oro_prepare("addForAgent", ["human1", "[\"ahead1 isOn table1\"]"],
                prepared(_, addForAgent, Args)).
test(pattern_left_as_text, true(Args == [["ahead1 isOn ?x"]])) :-
    oro_prepare("add", ["[\"ahead1 isOn ?x\"]"], prepared(_, add, Args)).
test(bad_statement_left_as_text, true(Args == [["ahead1 isOn"]])) :-
    oro_prepare("add", ["[\"ahead1 isOn\"]"], prepared(_, add, Args)).
test(find_not_parsed, true(Args == ["x", ["?x isOn table1"]])) :-
    oro_prepare("find", ["x", "[?x isOn table1]"], prepared(_, find, Args)).
test(unknown_method_not_prepared, true(P == request("nosuch", []))) :-
    oro_prepare("nosuch", [], P).
test(bad_set_not_prepared, true(P == request("add", ["[a b"]))) :-
    oro_prepare("add", ["[a b"], P).

%   Parsed statements, given again as triples, are the same triples: the
%   method then stores what it would have stored from the text.

test(parsed_statements_normal, true(Differ == [])) :-
    findall(S, normal_case(S), Statements),
    exclude(parsed_again_same, Statements, Differ).

:- end_tests(ahead_prepare).

prepare_case("add", ["[\"ahead1 isOn table1\", \"ahead2 rdfs:label \\\"a b\\\"\"]"]).
prepare_case("ADD", ["[\"ahead1 isOn table1\"]"]).
prepare_case("add", ["[\"ahead1 isOn\"]"]).
prepare_case("add", ["[\"ahead1 isOn ?x\"]"]).
prepare_case("add", ["[a b"]).
prepare_case("add", ["[\"ahead1 isOn table1\"]", "LONGTERM"]).
prepare_case("add", ["[\"ahead1 isOn table1\"]", "NOSUCH"]).
prepare_case("update", ["[\"ahead1 isOn table1\"]"]).
prepare_case("addForAgent", ["nobody", "[\"ahead1 isOn table1\"]"]).
prepare_case("check", ["[\"ahead1 isOn table1\"]"]).
prepare_case("find", ["x", "[?x isOn table1]"]).
prepare_case("nosuch", []).
prepare_case("hello", ["extra"]).
prepare_case("hello", []).

differs(Method-Params) :-
    test_ok(reset, []),
    test_server_context(Context),
    oro_dispatch(Context, Method, Params, Dispatched),
    test_ok(reset, []),
    oro_prepare(Method, Params, Prepared),
    oro_perform(Context, Prepared, Performed),
    Dispatched \== Performed.

test_server_context(_{peer:test, mutex:none, end:true, subscribers:slot([]),
                      max_params:4096}).

normal_case("ahead1 isOn table1").
normal_case("ahead1 rdfs:label \"a table\"").
normal_case("ahead1 rdfs:label \"une table\"@fr").
normal_case("ahead1 hasWeight 12").
normal_case("ahead1 hasWeight 1.5").
normal_case("ahead1 isVisible true").
normal_case("ahead1 hasName \"x\"^^xsd:string").
normal_case("ahead1 rdf:type oro:Table").
normal_case("ahead1 owl:sameAs ahead2").
normal_case("ahead1 isOn http://example.org/t#table1").
normal_case("ahead1 rdfs:comment \"quote \\\" and tab\\t\"").
normal_case("\"ahead1\" isOn table1").
normal_case("12 isOn table1").
normal_case("_:b1 isOn _:b2").
normal_case("<http://example.org/t#a> isOn table1").

parsed_again_same(Statement) :-
    oro_statements([Statement], Triples, []),
    oro_statements(Triples, Again, []),
    Again == Triples.

                 /*******************************
                 *            SERVER            *
                 *******************************/

:- begin_tests(ahead_server,
               [ setup(start_ahead),
                 cleanup(stop_ahead)
               ]).

test(pipelined_batches_all_added,
     true(Adds-Count-Used == Oks-1000-true)) :-
    test_ok(reset, []),
    used_ahead(_),
    batch_requests(p, 10, Requests),
    count_request(Count0),
    append(Requests, [Count0], All),
    pipelined(All, Replies),
    length(Adds, 10),
    append(Adds, [Last], Replies),
    length(Oks, 10),
    maplist(=(ok("")), Oks),
    prefixed(Last, "p", Found),
    length(Found, Count),
    used_ahead(Used).
test(replies_in_order_of_requests, true(Kinds == Expected)) :-
    test_ok(reset, []),
    batch_request(add, q, 1, Add1),
    check_request("q1_3 isOn table1", Check1),
    batch_text(q, 2, Batch2),
    format(string(Bad), "add\n[~s, \"broken isOn\"]\n#end#\n", [Batch2]),
    check_request("q2_3 isOn table1", Check2),
    batch_request(add, q, 3, Add3),
    Stats = "stats\n#end#\n",
    check_request("q3_3 isOn table1", Check3),
    pipelined([Add1, Check1, Bad, Check2, Add3, Stats, Check3], Replies),
    maplist(reply_kind, Replies, Kinds),
    Expected = [ok(""), ok("true"), error, ok("false"), ok(""), ok(map),
                ok("true")].
test(error_as_when_alone, true(Ahead == Alone)) :-
    test_ok(reset, []),
    batch_text(r, 1, Batch),
    format(string(Bad), "add\n[~s, \"broken isOn\"]\n#end#\n", [Batch]),
    batch_request(add, r, 2, Add2),
    pipelined([Bad, Add2], [Ahead, _]),
    test_ok(reset, []),
    pipelined([Bad], [Alone]).
test(close_after_pipelined, true(Replies == Expected)) :-
    test_ok(reset, []),
    batch_requests(s, 4, Requests),
    append(Requests, ["close\n#end#\n"], All),
    Expected = [ok(""), ok(""), ok(""), ok(""), closing, end_of_file],
    atomics_to_string(All, Text),
    connected(C, ( oro_send_raw(C, Text),
                   test_receive_n(C, 6, Replies)
                 )).
test(client_leaving_ends_connection, true(Whole-Alive == true-true)) :-
    test_ok(reset, []),
    batch_requests(t, 30, Requests),
    atomics_to_string(Requests, Text),
    connected(C, oro_send_raw(C, Text)),
    test_wait_until(test_server_connections(0), 10),
    count_request(Count),
    pipelined([Count], [Reply]),
    prefixed(Reply, "t", Found),
    length(Found, N),
    (   N mod 100 =:= 0
    ->  Whole = true
    ;   Whole = N
    ),
    (   test_call(hello, [], ok(_))
    ->  Alive = true
    ;   Alive = false
    ).
test(small_requests_not_ahead, true(Used == false)) :-
    test_ok(reset, []),
    used_ahead(_),
    numlist(1, 50, Ks),
    maplist([K, R]>>format(string(R), "add\n[\"u~d isOn table1\"]\n#end#\n",
                           [K]),
            Ks, Requests),
    pipelined(Requests, Replies),
    length(Replies, 50),
    maplist(==(ok("")), Replies),
    used_ahead(Used).
test(helper_ends_with_connection, true(Used-Back == true-true)) :-
    test_ok(reset, []),
    used_ahead(_),
    thread_count(Before),
    batch_requests(v, 5, Requests),
    pipelined(Requests, _),
    used_ahead(Used),
    test_wait_until(test_server_connections(0), 10),
    test_bool(test_wait_until(thread_count(Before), 10), Back).
test(at_most_two_wait_for_the_helper, true(Got == [p1, p2]-none-p3)) :-
    % White box: a helper that answers nothing (its queues are the
    % test's); the third request is given only once one is answered.
    message_queue_create(Jobs),
    message_queue_create(Done),
    Ahead = ahead(helper(none, Jobs, Done, 0)),
    call_cleanup(
        ( oro_server:send_ahead(Ahead, p1),
          oro_server:send_ahead(Ahead, p2),
          thread_create(oro_server:send_ahead(Ahead, p3), Sender, []),
          queued(Jobs, Given),
          (   thread_get_message(Jobs, answer(Early), [timeout(0.2)])
          ->  true
          ;   Early = none
          ),
          thread_send_message(Done, done),
          (   thread_get_message(Jobs, answer(Late), [timeout(10)])
          ->  true
          ;   Late = none
          ),
          thread_join(Sender, _),
          Got = Given-Early-Late
        ),
        ( message_queue_destroy(Jobs),
          message_queue_destroy(Done)
        )).
test(events_after_the_reply_that_caused_them,
     true(First-Oks-Events == ok-5-true)) :-
    test_ok(reset, []),
    batch_requests(w, 5, Requests),
    atomics_to_string(Requests, Text),
    connected(C, ( oro_call(C, registerEvent,
                            ["NEW_INSTANCE", "ON_TRUE", "x", "[?x isOn table1]"],
                            ok(_), 10),
                   oro_send_raw(C, Text),
                   messages_until_oks(C, 5, 100, Messages)
                 )),
    Messages = [Message1|_],
    functor(Message1, First, _),
    aggregate_all(count, member(ok(_), Messages), Oks),
    (   memberchk(event(_, _), Messages)
    ->  Events = true
    ;   Events = false
    ).

:- end_tests(ahead_server).

%   queued(+Queue, -Ps): the answer(P) messages waiting on Queue, taken.

queued(Queue, [P|Ps]) :-
    thread_get_message(Queue, answer(P), [timeout(0)]),
    !,
    queued(Queue, Ps).
queued(_, []).

thread_count(N) :-
    aggregate_all(count, thread_property(_, status(running)), N).

%   messages_until_oks(+Conn, +N, +Max, -Messages): the messages of
%   Conn in arrival order until N `ok` replies and one event after
%   them (at most Max messages, each waited for 10 s at most).

messages_until_oks(C, N, Max, [M|Ms]) :-
    Max > 0,
    oro_receive(C, M, 10),
    M \== timeout,
    M \== end_of_file,
    !,
    (   M = ok(_)
    ->  N1 is N - 1
    ;   N1 = N
    ),
    (   N1 =< 0,
        M = event(_, _)
    ->  Ms = []
    ;   Max1 is Max - 1,
        messages_until_oks(C, N1, Max1, Ms)
    ).
messages_until_oks(_, _, _, []).

start_ahead :-
    test_server_start_testsuite,
    retractall(ahead_used(_)),
    debug(oro(server)).

stop_ahead :-
    nodebug(oro(server)),
    retractall(ahead_used(_)),
    test_server_stop.

:- multifile prolog:debug_print_hook/3.

prolog:debug_print_hook(oro(server), Format, Args) :-
    (   Format == 'Connection ~q: requests ahead'
    ->  strip_module(Args, _, [Peer]),
        assertz(ahead_used(Peer))
    ;   true
    ).

%   used_ahead(-Used): whether a connection used its helper since the
%   last call.

used_ahead(Used) :-
    (   retract(ahead_used(_))
    ->  Used = true,
        retractall(ahead_used(_))
    ;   Used = false
    ).

%   pipelined(+Requests, -Replies): the texts of Requests sent in one
%   write on a new connection, and a reply for each.

pipelined(Requests, Replies) :-
    atomics_to_string(Requests, Text),
    length(Requests, N),
    connected(C, ( oro_send_raw(C, Text),
                   test_receive_n(C, N, Replies)
                 )).

%   connected(-Conn, :Goal): Goal once on a new connection Conn to the
%   unit's server (requests sent at once: nodelay), closed afterwards.

connected(C, Goal) :-
    test_server_port(Port),
    setup_call_cleanup(
        oro_connect(Port, C, [nodelay(true)]),
        once(Goal),
        oro_disconnect(C)).

%   batch_requests(+Prefix, +N, -Requests): N adds of batch_request/4.

batch_requests(Prefix, N, Requests) :-
    numlist(1, N, Ks),
    maplist(batch_request(add, Prefix), Ks, Requests).

%   batch_request(+Method, +Prefix, +K, -Request): a request of 100
%   statements `PrefixK_I isOn tableJ`, over the ahead threshold.

batch_request(Method, Prefix, K, Request) :-
    batch_text(Prefix, K, Batch),
    format(string(Request), "~w\n[~s]\n#end#\n", [Method, Batch]).

batch_text(Prefix, K, Batch) :-
    numlist(1, 100, Is),
    maplist({Prefix, K}/[I, S]>>( J is I mod 3 + 1,
                      format(string(S), "\"~w~d_~d isOn table~d\"",
                             [Prefix, K, I, J])
                    ),
            Is, Statements),
    atomic_list_concat(Statements, ', ', Batch).

check_request(Statement, Request) :-
    format(string(Request), "check\n[\"~w\"]\n#end#\n", [Statement]).

count_request("find\nx\n[?x isOn ?t]\n#end#\n").

%   prefixed(+Reply, +Prefix, -Names): the names of the list Reply that
%   start with Prefix (the test ontology has things on tables too).

prefixed(Reply, Prefix, Names) :-
    test_set(Reply, All),
    include({Prefix}/[N]>>string_concat(Prefix, _, N), All, Names).

reply_kind(ok(V), ok(Kind)) :-
    (   sub_string(V, 0, 1, _, "{")
    ->  Kind = map
    ;   Kind = V
    ).
reply_kind(error(_, _), error).
