:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module(library(oro)).

/*  Concurrency soak over real sockets (issue #8).

    50 clients, each on its own connection and thread, run a seeded
    random mix of operations at the same time: add, remove, find and
    check on subjects of their own (sk_<client>_<j>), registerEvent
    (FACT_CHECKING and NEW_INSTANCE on their own subjects), clearEvent
    of their own watchers, clearEvents, and adds on shared subjects
    whose final state does not depend on the order (a union).  Each
    client keeps the model of what its subjects must hold, so that

      - every reply arrives (bounded waits) and is the one expected:
        find and check answers are exact, since no one else touches a
        client's subjects; clearEvent of a watcher another client's
        clearEvents removed is the only error allowed;
      - events interleaved with replies are read aside, and every event
        a client receives is one of its own watchers';
      - the whole run ends within a bound (no deadlock), and the
        server's threads go back to what they were (no connection or
        event delivery thread left behind);
      - the final store is the store before plus each client's model
        plus the shared statements, and equals a sequential replay of
        the acknowledged adds and removes, client after client, on a
        fresh store (oro_reset/0 then oro_add/2, oro_remove/2).

    Sizes: 50 clients x 1,000 operations (the full size of the issue)
    by default, about 15 s on 2 cores; 50 x 5,000 with
    ORO_LONG_TESTS=1.  The seed is printed; ORO_SOAK_SEED=N sends the
    same operations again (not in the same interleaving).

    Run: cd /work/main && swipl -g run_tests -t halt test/test_soak.pl
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(random)).
:- use_module(library(ordsets)).
:- use_module(library(aggregate)).
:- use_module(library(oro/oro_store)).

soak_sizes(Clients, Operations) :-
    (   getenv('ORO_LONG_TESTS', '1')
    ->  Clients = 50,
        Operations = 5000
    ;   Clients = 50,
        Operations = 1000
    ).

soak_seed(Seed) :-
    test_seed('ORO_SOAK_SEED', Seed).

%   Each client has 4 subjects, each with values among 8 objects.

soak_subjects(4).
soak_objects(8).

soak_store(Triples) :-
    findall(rdf(S, P, O), oro_asserted(myself, S, P, O), Triples0),
    sort(Triples0, Triples).

soak_iri(Name, IRI) :-
    atom_concat('http://kb.openrobots.org#', Name, IRI).

%   A statement of client I is sk(J, M): `sk_I_J skp sko_M`.

soak_text(I, sk(J, M), Text) :-
    format(string(Text), "sk_~d_~d skp sko_~d", [I, J, M]).

soak_triple(I, sk(J, M), rdf(S, P, O)) :-
    format(atom(SName), "sk_~d_~d", [I, J]),
    format(atom(OName), "sko_~d", [M]),
    soak_iri(SName, S),
    soak_iri(skp, P),
    soak_iri(OName, O).

soak_random_statement(sk(J, M)) :-
    soak_subjects(NS),
    soak_objects(NO),
    random_between(1, NS, J),
    random_between(1, NO, M).

soak_random_statements(Statements) :-
    random_between(1, 3, K),
    length(Statements, K),
    maplist(soak_random_statement, Statements).

%   The shared statements of client I: a tag on a shared subject, and
%   one statement every client adds.

soak_shared(I, K, [Tag, "sk_shared_all skp sk_common"]) :-
    format(string(Tag), "sk_shared_~d skp sk_tag_~d", [K, I]).

soak_shared_triple(Text, rdf(S, P, O)) :-
    split_string(Text, " ", "", [ST, PT, OT]),
    maplist(atom_string, [SA, PA, OA], [ST, PT, OT]),
    soak_iri(SA, S),
    soak_iri(PA, P),
    soak_iri(OA, O).


                 /*******************************
                 *            A CLIENT          *
                 *******************************/

%   The state of client I: c(I, Model, Shared, Watchers, Ever, Log,
%   Problems)
%
%     - Model: ordset of its sk(J, M) that must hold
%     - Shared: the shared statement texts it added (acknowledged)
%     - Watchers: ids of its watchers not cleared by itself
%     - Ever: ids of all the watchers it registered
%     - Log: acknowledged changes, newest first: add(Texts),
%       remove(Texts)
%     - Problems: replies that were not as expected, newest first

soak_client(Queue, Port, I, Seed, Operations) :-
    ClientSeed is Seed + I,
    set_random(seed(ClientSeed)),
    catch(soak_session(Port, I, Operations, Result), E,
          Result = result(I, [], [], [], [exception(E)], [])),
    thread_send_message(Queue, Result).

soak_session(Port, I, Operations, result(I, Model, Shared, Log, Problems, Events)) :-
    setup_call_cleanup(
        oro_connect(Port, Conn),
        ( soak_operations(Operations, Conn, c(I, [], [], [], [], [], []), S),
          soak_events(Conn, 100000, Events)
        ),
        oro_disconnect(Conn)),
    S = c(_, Model, Shared, _, Ever, Log0, Problems0),
    reverse(Log0, Log),
    include(soak_foreign_event(Ever), Events, Foreign),
    maplist(soak_foreign_problem, Foreign, ForeignProblems),
    reverse(Problems0, Problems1),
    append(Problems1, ForeignProblems, Problems2),
    length(Problems2, NP),
    (   NP > 10
    ->  length(Problems, 10),
        append(Problems, _, Problems2)
    ;   Problems = Problems2
    ).

soak_foreign_event(Ever, event(Id, _)) :-
    atom_string(A, Id),
    \+ memberchk(A, Ever).

soak_foreign_problem(Event, foreign_event(Event)).

%   soak_events(+Conn, +Max, -Events): the events queued or pending on
%   Conn now (at most Max).

soak_events(Conn, Max, Events) :-
    (   Max =< 0
    ->  Events = []
    ;   oro_next_event(Conn, Event, 0.2),
        (   Event = event(_, _)
        ->  Events = [Event|Rest],
            Max1 is Max - 1,
            soak_events(Conn, Max1, Rest)
        ;   Events = []
        )
    ).

soak_operations(0, _, S, S) :-
    !.
soak_operations(_, _, S, S) :-
    S = c(_, _, _, _, _, _, [stop(_)|_]),
    !.
soak_operations(N, Conn, S0, S) :-
    random_between(1, 100, R),
    soak_operation(R, Conn, S0, S1),
    N1 is N - 1,
    soak_operations(N1, Conn, S1, S).

soak_call(Conn, Method, Params, Reply) :-
    oro_call(Conn, Method, Params, Reply, 60).

%   soak_operation(+Roll, +Conn, +S0, -S)

soak_operation(R, Conn, S0, S) :-                       % add
    R =< 30,
    !,
    S0 = c(I, Model0, Sh, W, E, Log, P),
    soak_random_statements(Statements),
    maplist(soak_text(I), Statements, Texts),
    test_set_text(Texts, Set),
    soak_call(Conn, add, [Set], Reply),
    (   Reply == ok("")
    ->  list_to_ord_set(Statements, New),
        ord_union(Model0, New, Model),
        S = c(I, Model, Sh, W, E, [add(Texts)|Log], P)
    ;   soak_problem(add(Set), Reply, S0, S)
    ).
soak_operation(R, Conn, S0, S) :-                       % remove
    R =< 50,
    !,
    S0 = c(I, Model0, Sh, W, E, Log, P),
    soak_random_statements(Statements),
    maplist(soak_text(I), Statements, Texts),
    test_set_text(Texts, Set),
    soak_call(Conn, remove, [Set], Reply),
    (   Reply == ok("")
    ->  list_to_ord_set(Statements, Old),
        ord_subtract(Model0, Old, Model),
        S = c(I, Model, Sh, W, E, [remove(Texts)|Log], P)
    ;   soak_problem(remove(Set), Reply, S0, S)
    ).
soak_operation(R, Conn, S0, S) :-                       % find
    R =< 65,
    !,
    S0 = c(I, Model, _, _, _, _, _),
    soak_subjects(NS),
    random_between(1, NS, J),
    format(string(Pattern), "[sk_~d_~d skp ?x]", [I, J]),
    soak_call(Conn, find, ["x", Pattern], Reply),
    findall(Name, ( member(sk(J, M), Model),
                    format(string(Name), "sko_~d", [M])
                  ), Names0),
    msort(Names0, Names),
    (   Reply = ok(Line),
        catch(test_json(Line, Values0), _, fail),
        msort(Values0, Values),
        Values == Names
    ->  S = S0
    ;   soak_problem(find(Pattern, expected(Names)), Reply, S0, S)
    ).
soak_operation(R, Conn, S0, S) :-                       % check
    R =< 80,
    !,
    S0 = c(I, Model, _, _, _, _, _),
    random_between(1, 2, K),
    length(Statements, K),
    maplist(soak_random_statement, Statements),
    maplist(soak_text(I), Statements, Texts),
    test_set_text(Texts, Set),
    (   forall(member(St, Statements), memberchk(St, Model))
    ->  Expected = ok("true")
    ;   Expected = ok("false")
    ),
    soak_call(Conn, check, [Set], Reply),
    (   Reply == Expected
    ->  S = S0
    ;   soak_problem(check(Set, Expected), Reply, S0, S)
    ).
soak_operation(R, Conn, S0, S) :-                       % registerEvent
    R =< 88,
    !,
    S0 = c(I, Model, Sh, W, E, Log, P),
    soak_subjects(NS),
    random_between(1, NS, J),
    (   maybe(0.5)
    ->  soak_objects(NO),
        random_between(1, NO, M),
        random_member(Trigger, ["ON_TRUE", "ON_TOGGLE", "ON_FALSE"]),
        format(string(Pattern), "[sk_~d_~d skp sko_~d]", [I, J, M]),
        Params = ["FACT_CHECKING", Trigger, Pattern]
    ;   random_member(Trigger, ["ON_TRUE", "ON_TOGGLE"]),
        format(string(Pattern), "[sk_~d_~d skp ?x]", [I, J]),
        Params = ["NEW_INSTANCE", Trigger, "x", Pattern]
    ),
    soak_call(Conn, registerEvent, Params, Reply),
    (   Reply = ok(Line),
        atom_string(Id, Line),
        uuid_like(Id)
    ->  S = c(I, Model, Sh, [Id|W], [Id|E], Log, P)
    ;   soak_problem(registerEvent(Params), Reply, S0, S)
    ).
soak_operation(R, Conn, S0, S) :-                       % clearEvent
    R =< 93,
    !,
    S0 = c(I, Model, Sh, W0, E, Log, P),
    (   W0 == []
    ->  S = S0
    ;   random_member(Id, W0),
        soak_call(Conn, clearEvent, [Id], Reply),
        (   (   Reply == ok("")
            ;   Reply = error(Name, _),     % cleared by a clearEvents
                sub_string(Name, _, _, 0, "EventNotFoundException")
            )
        ->  delete(W0, Id, W),
            S = c(I, Model, Sh, W, E, Log, P)
        ;   soak_problem(clearEvent(Id), Reply, S0, S)
        )
    ).
soak_operation(R, Conn, S0, S) :-                       % clearEvents
    R =< 94,
    !,
    soak_call(Conn, clearEvents, [], Reply),
    (   Reply == ok("")
    ->  S = S0
    ;   soak_problem(clearEvents, Reply, S0, S)
    ).
soak_operation(_, Conn, S0, S) :-                       % shared
    S0 = c(I, Model, Sh0, W, E, Log, P),
    random_between(0, 4, K),
    soak_shared(I, K, Texts),
    test_set_text(Texts, Set),
    soak_call(Conn, add, [Set], Reply),
    (   Reply == ok("")
    ->  append(Texts, Sh0, Sh),
        S = c(I, Model, Sh, W, E, [add(Texts)|Log], P)
    ;   soak_problem(shared(Set), Reply, S0, S)
    ).

uuid_like(Id) :-
    atom_length(Id, 36),
    sub_atom(Id, 8, 1, _, -).

%   soak_problem(+Request, +Reply, +S0, -S): record it; a reply that
%   is no reply (timeout, closed connection, garbage) stops the client.

soak_problem(Request, Reply, c(I, M, Sh, W, E, L, P),
             c(I, M, Sh, W, E, L, [Problem|P])) :-
    (   ( Reply = ok(_) ; Reply = error(_, _) )
    ->  Problem = wrong(Request, Reply)
    ;   Problem = stop(Request, Reply)
    ).


                 /*******************************
                 *             RUN              *
                 *******************************/

soak_run(Port, Clients, Operations, Seed, Results) :-
    message_queue_create(Queue),
    call_cleanup(
        ( forall(between(1, Clients, I),
                 thread_create(soak_client(Queue, Port, I, Seed, Operations),
                               _, [detached(true)])),
          get_time(Now),
          Deadline is Now + 600,
          length(Results, Clients),
          maplist(soak_result(Queue, Deadline), Results)
        ),
        message_queue_destroy(Queue)).

soak_result(Queue, Deadline, Result) :-
    get_time(Now),
    Left is max(0, Deadline - Now),
    (   thread_get_message(Queue, Result0, [timeout(Left)])
    ->  Result = Result0
    ;   Result = result(none, [], [], [], [stop(deadline_passed)], [])
    ).

soak_expected(result(I, Model, Shared, _, _, _), Triples) :-
    maplist(soak_triple(I), Model, T1),
    maplist(soak_shared_triple, Shared, T2),
    append(T1, T2, Triples).

soak_problems(result(I, _, _, _, Problems, _), I-Problems).

soak_event_count(result(_, _, _, _, _, Events), N) :-
    length(Events, N).

%   soak_replay(+Results): the acknowledged changes of each client, in
%   its order, client after client, on a fresh store.

soak_replay(Results) :-
    oro_reset,
    forall(member(result(_, _, _, Log, _, _), Results),
           forall(member(Change, Log),
                  soak_replay_change(Change))).

soak_replay_change(add(Texts)) :-
    oro_add(myself, Texts).
soak_replay_change(remove(Texts)) :-
    oro_remove(myself, Texts).

%   soak_threads(-N): the running threads without an alias: the
%   accept thread, connection workers, event delivery threads (library
%   and system threads such as rdf_db's garbage collector, started on
%   first need, have one).

soak_threads(N) :-
    aggregate_all(count,
                  ( thread_property(T, status(running)),
                    \+ thread_property(T, alias(_))
                  ),
                  N).

soak_diff(Expected, Actual, Diff) :-
    test_diff(Expected, Actual, 5, Diff).

%   The server rebuilds its store every few dozen names (see
%   oro_store_rebuild/0): the final store must still be the replay's.

:- begin_tests(soak, [ setup(test_server_start_testsuite([rebuild_garbage(50)])),
                       cleanup(test_server_stop)
                     ]).

test(clients,
     [ true(Problems-Diff-ReplayDiff-Threads-Answer ==
            NoProblems-diff(0, [], 0, [])-diff(0, [], 0, [])-released-ok("true"))
     ]) :-
    soak_seed(Seed),
    soak_sizes(Clients, Operations),
    format(user_error,
           "~N% test_soak: seed ~d, ~d clients x ~D operations \c
            (ORO_SOAK_SEED=~d replays it)~n",
           [Seed, Clients, Operations, Seed]),
    test_server_port(Port),
    soak_store(Before),
    soak_threads(Threads0),
    soak_run(Port, Clients, Operations, Seed, Results0),
    msort(Results0, Results),
    maplist(soak_problems, Results, Problems),
    findall(I-[], between(1, Clients, I), NoProblems),
    (   test_wait_until(( soak_threads(N), N =< Threads0 ), 30)
    ->  Threads = released
    ;   soak_threads(N),
        Threads = left(Threads0, N)
    ),
    test_call(check, ["[baboon rdf:type Animal]"], Answer),
    maplist(soak_expected, Results, ExpectedLists),
    append([Before|ExpectedLists], Expected0),
    sort(Expected0, Expected),
    soak_store(After),
    soak_diff(Expected, After, Diff),
    soak_replay(Results),
    soak_store(Replayed),
    soak_diff(Replayed, After, ReplayDiff),
    maplist(soak_event_count, Results, EventCounts),
    sum_list(EventCounts, Events),
    assertion(Events > 0).

:- end_tests(soak).
