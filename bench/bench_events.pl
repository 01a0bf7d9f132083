/*  oro events benchmark: latency of pushed events and cost of changes
    with many watchers registered, over the socket and in process.

        swipl bench/bench_events.pl [--samples=200] [--levels=1,100,1000]
                                    [--issue=true] [--world=100000]
                                    [--hops=true] [--reply=true]

    (default levels: 1,100,1000,1000-other; W-other puts the W watchers on
    another predicate)

    1. Levels.  It starts the real server (server/oro_server.pl
    --port=0) as a child process and, on one connection, for each level
    W:

      - resets the server, registers W NEW_INSTANCE watchers with
        distinct patterns `?o isOn shelf_I` (all on the predicate the
        measured changes touch), then the measured watcher
        `?o isOn bench_table`, last;
      - event latency: time from sending `add [objN isOn bench_table]`
        (a new object each sample) to receiving the pushed event
        `["objN"]` (median, p99, and the median of the part after the
        `ok` reply arrived); a sample whose event does not come within
        5 s (or comes with another content) counts as missed;
      - a level W-other registers the W watchers on another predicate
        (`?o isIn box_I`): the changes do not touch them (index by
        predicate);
      - cost of a plain add: round trip of `add` on a predicate no
        watcher uses (`objN hasColor red`) and on the watched one
        (`objN isOn floor`, firing nothing), with W watchers and with
        none (level 0).

    2. The case of issue #9 (`--issue`): a fresh server holding the
    synthetic world of bench_common (`--world` triples, 25,000 objects
    on 50 pieces of furniture at 100k), 333 classes `Kind_K` under
    Artifact, and 1,000 NEW_INSTANCE watchers of varied patterns, one
    in three of each: `?x isOn T` (T a piece of furniture holding 500
    objects, or an empty table), `?x rdf:type Kind_K`, `?x isAt room_K`.
    Each sample adds one statement that fires exactly one of them, a
    different one each time, in turn `obj isOn T`, `obj rdf:type
    Kind_K` and `obj isIn room_K` (isIn is a sub-property of isAt):
    event latency median, p99 and max, and missed events (none or
    another content within 5 s).

    3. Hops (`--hops`): the same world and watchers in this process,
    one subscriber for all of them, to split the latency of one event
    into its steps: the writer's add (no watcher concerned; firing one,
    with the monitor's snapshot and message), a bare thread-to-thread
    message, the writer's add until the watcher thread has evaluated
    the change (oro_events_sync/0), and until the subscriber's delivery
    thread calls its goal.

    4. Replies carrying events (`--reply`): what an `add` costs, round
    trip on one connection A, now that the events it fires for A's
    watchers travel with its reply (A's worker waits until the watcher
    thread has evaluated the change, then writes the reply and the
    events in one write).  Cases: no watcher at all; a watcher of
    another connection B on the predicate the add touches (A does not
    wait); a watcher of A on another predicate (the change is not sent
    to the watcher thread: no wait); a watcher of A on the predicate,
    not firing (A waits for its evaluation); the same watcher firing
    (time until the reply and the event are both read).

    5. Many watchers (`--many=10000`, 0 to skip): for each of three
    kinds, NEW_INSTANCE `?o isOn place_I`, NEW_INSTANCE `?o behind
    place_I` (a transitive property) and FACT_CHECKING `?o isOn
    place_I`, one connection of a fresh server registers N watchers with
    distinct patterns: registrations a second over the first and the last
    thousand; then registering the first thousand again (each joins its
    identical watcher); an add on a predicate no watcher uses (until
    its reply), on the watched predicate firing nothing (until the
    watcher thread has processed it: a registration of a watcher already
    registered follows it), and one firing one watcher (its event's
    latency; NEW_INSTANCE only), each the median of `--samples` after a
    first add (which evaluates the FACT_CHECKING watchers, not evaluated
    until a change comes, and is shown apart, timed as the watched
    add); clearing the N watchers with clearEvent one by one, and,
    registered again, with clearEvents (a clearing is answered once
    done).  In this process, what a connection's close does: a
    subscriber of N watchers destroyed (oro_subscriber_destroy/2).

    Between phases a registration of an already registered watcher
    serves as a barrier: it is answered once the watcher thread has
    processed every change before it.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(samples, samples, nonneg).
opt_type(levels, levels, term).
opt_type(issue, issue, boolean).
opt_type(world, world, nonneg).
opt_type(hops, hops, boolean).
opt_type(reply, reply, boolean).
opt_type(many, many, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(samples(Samples), Options, 200),
    bench_list_option(levels(Levels), Options, [1, 100, 1000, 1000-other]),
    option(issue(Issue), Options, true),
    option(world(World), Options, 100000),
    option(hops(Hops), Options, true),
    option(reply(Reply), Options, true),
    option(many(Many), Options, 10000),
    bench_machine,
    (   Levels == []
    ->  true
    ;   bench_with_server([], Port, _, bench(Port, Samples, Levels))
    ),
    (   Issue == true
    ->  bench_with_server([], Port2, _, issue(Port2, World, Samples))
    ;   true
    ),
    (   Reply == true
    ->  bench_with_server([], Port3, _, reply_costs(Port3, Samples))
    ;   true
    ),
    (   Hops == true
    ->  hops(World, Samples)
    ;   true
    ),
    (   Many > 0
    ->  many(Many, Samples)
    ;   true
    ).

%   call_ok(+Conn, +Method, +Params[, -Value]): a request whose next
%   message must be its `ok` (no event is pending when it is used),
%   within 30 s.

call_ok(Conn, Method, Params, Value) :-
    bench_call(Conn, Method, Params, Value, 30).

call_ok(Conn, Method, Params) :-
    bench_call(Conn, Method, Params, _, 30).

		 /*******************************
		 *            LEVELS            *
		 *******************************/

bench(Port, Samples, Levels) :-
    bench_with_connection(
        Port, Conn,
        ( format("~n~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
                 [watchers, 'register', 'event median', 'event p99',
                  'after ok', missed, 'add unwatched', 'add watched']),
          level(Conn, 0, Samples),
          forall(member(W, Levels), level(Conn, W, Samples))
        )).

level(Conn, Level, Samples) :-
    (   Level = W-other
    ->  Shelf = "[?o isIn box_~d]"
    ;   W = Level,
        Shelf = "[?o isOn shelf_~d]"
    ),
    call_ok(Conn, reset, []),
    register_shelves(Conn, W, Shelf, RegTimes),
    (   W > 0
    ->  measured_pattern(Pattern),
        call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern], Id),
        latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed),
        barrier(Conn)
    ;   Latencies = [],
        AfterOk = [],
        Missed = '-'
    ),
    add_times(Conn, W, unwatched, Samples, Unwatched),
    barrier(Conn),
    add_times(Conn, W, watched, Samples, Watched),
    barrier(Conn),
    row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched).

measured_pattern("[?o isOn bench_table]").

register_shelves(Conn, W, Shelf, Times) :-
    findall(T,
            ( between(1, W, I),
              format(string(P), Shelf, [I]),
              bench_time(call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", P]), T)
            ), Times).

%   barrier(+Conn): returns once every change sent before has been
%   processed by the watcher thread (a registration is queued behind
%   them; this one is a duplicate, so it changes nothing).

barrier(Conn) :-
    measured_pattern(Pattern),
    call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Pattern]).

latencies(Conn, Id, W, Samples, Latencies, AfterOk, Missed) :-
    findall(Result,
            ( between(1, Samples, I),
              latency(Conn, Id, W, I, Result)
            ), Results),
    findall(L, member(L-_, Results), Latencies),
    findall(A, member(_-A, Results), AfterOk),
    exclude(is_pair, Results, MissedList),
    length(MissedList, Missed).

is_pair(_-_).

latency(Conn, Id, W, I, Result) :-
    format(atom(Obj), "obj_~d_~d", [W, I]),
    format(string(Stmt), "[~w isOn bench_table]", [Obj]),
    format(string(Expected), "[\"~w\"]", [Obj]),
    event_latency(Conn, Id, Stmt, Expected, Result).

%   event_latency(+Conn, +Id, +Stmt, +Expected, -Result): send `add
%   Stmt`; Result is Latency-AfterOk (microseconds from sending, and
%   from the `ok`, to the event Id with content Expected), or
%   missed(Message).

event_latency(Conn, Id, Stmt, Expected, Result) :-
    get_time(T0),
    bench_send(Conn, add, [Stmt]),
    bench_receive(Conn, Reply, 30),
    (   Reply = ok(_)
    ->  get_time(TOk),
        bench_receive(Conn, Event, 5),
        get_time(T1),
        (   Event = event(Id, Expected)
        ->  Latency is (T1 - T0) * 1.0e6,
            After is (T1 - TOk) * 1.0e6,
            Result = Latency-After
        ;   Result = missed(Event)
        )
    ;   Result = missed(Reply)
    ).

add_times(Conn, W, Kind, Samples, Times) :-
    findall(T,
            ( between(1, Samples, I),
              add_statement(Kind, W, I, Stmt),
              bench_time(call_ok(Conn, add, [Stmt]), T)
            ), Times).

add_statement(unwatched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d hasColor red]", [W, I]).
add_statement(watched, W, I, Stmt) :-
    format(string(Stmt), "[plain_~d_~d isOn floor]", [W, I]).

		 /*******************************
		 *        ISSUE #9 CASE         *
		 *******************************/

%   issue_watchers(-Watchers): the 1,000 watchers, as w(N, Pattern,
%   Fire) with Fire(+Obj, -Statement) the statement that makes Obj a new
%   value of watcher N only.

issue_watchers(Watchers) :-
    findall(w(N, Pattern, Fire),
            ( between(0, 999, N),
              issue_watcher(N, Pattern, Fire)
            ), Watchers).

issue_watcher(N, Pattern, fire("~w isOn ~w", Table)) :-
    N mod 3 =:= 0,
    !,
    K is N // 3,
    (   K < 50
    ->  format(atom(Table), "furniture~d", [K])     % 500 objects on it
    ;   format(atom(Table), "table_~d", [K])
    ),
    format(string(Pattern), "?x isOn ~w", [Table]).
issue_watcher(N, Pattern, fire("~w rdf:type ~w", Class)) :-
    N mod 3 =:= 1,
    !,
    K is N // 3,
    format(atom(Class), "Kind_~d", [K]),
    format(string(Pattern), "?x rdf:type ~w", [Class]).
issue_watcher(N, Pattern, fire("~w isIn ~w", Room)) :-
    K is N // 3,
    format(atom(Room), "room_~d", [K]),
    format(string(Pattern), "?x isAt ~w", [Room]).

issue_classes(Statements) :-
    findall(S, ( between(0, 332, K),
                 format(string(S), "Kind_~d rdfs:subClassOf Artifact", [K])
               ), Statements).

fire_statement(fire(Format, Arg), Obj, Statement) :-
    format(string(Statement), Format, [Obj, Arg]).

%   issue_sample(+I, -N): the watcher fired by sample I: every watcher
%   in turn, from a stride prime to 1,000.

issue_sample(I, N) :-
    N is (I * 337) mod 1000.

issue(Port, World, Samples) :-
    bench_with_connection(Port, Conn, issue_run(Conn, World, Samples)).

issue_run(Conn, World, Samples) :-
    call_ok(Conn, reset, []),
    bench_world(World, Texts),
    bench_batches(Texts, 100, Batches),
    forall(member(B, Batches), call_ok(Conn, add, [B])),
    issue_classes(Classes),
    call_ok(Conn, add, [Classes]),
    issue_watchers(Watchers),
    findall(N-Id-T,
            ( member(w(N, Pattern, _), Watchers),
              bench_time(call_ok(Conn, registerEvent,
                                 ["NEW_INSTANCE", "ON_TRUE", "x", [Pattern]], Id),
                         T)
            ), Registered),
    findall(T, member(_-_-T, Registered), RegTimes),
    findall(Result,
            ( between(1, Samples, I),
              issue_sample(I, N),
              memberchk(N-Id-_, Registered),
              memberchk(w(N, _, Fire), Watchers),
              format(atom(Obj), "issue_obj_~d", [I]),
              fire_statement(Fire, Obj, Stmt),
              format(string(Text), "[~w]", [Stmt]),
              format(string(Expected), "[\"~w\"]", [Obj]),
              event_latency(Conn, Id, Text, Expected, Result)
            ), Results),
    findall(L, member(L-_, Results), Latencies),
    findall(A, member(_-A, Results), AfterOk),
    exclude(is_pair, Results, MissedList),
    length(MissedList, Missed),
    format("~nIssue #9: 1,000 NEW_INSTANCE watchers (isOn / rdf:type / isAt), \c
            ~D asserted triples, over the socket~n", [World]),
    format("~w~t~12|~w~t~14+~w~t~14+~w~t~14+~w~t~14+~w~n",
           ['register', 'event median', 'event p99', 'event max',
            'after ok', missed]),
    median_text(RegTimes, Reg),
    bench_summary(Latencies, LMedian, LP99),
    bench_micros(LMedian, LMed),
    bench_micros(LP99, LP),
    max_text(Latencies, LMax),
    median_text(AfterOk, AMed),
    format("~w~t~12|~w~t~14+~w~t~14+~w~t~14+~w~t~14+~w~n",
           [Reg, LMed, LP, LMax, AMed, Missed]),
    flush_output.

max_text([], -) :-
    !.
max_text(Times, Text) :-
    max_list(Times, Max),
    bench_micros(Max, Text).

		 /*******************************
		 *      REPLIES WITH EVENTS     *
		 *******************************/

reply_costs(Port, Samples) :-
    bench_with_connection(
        Port, A,
        bench_with_connection(Port, B, reply_cases(A, B, Samples))).

reply_cases(A, B, Samples) :-
    format("~nAn add and the events it fires for its own connection, \c
            round trip on that connection~n", []),
    format("~w~t~56|~w~t~14+~w~n", [case, median, p99]),
    call_ok(A, reset, []),
    reply_case(A, 'no watcher', Samples, "[rc_none_~d hasColor red]", no),
    call_ok(B, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", "[?o isOn rc_b_table]"]),
    reply_case(A, 'watcher of another connection, same predicate', Samples,
               "[rc_other_~d isOn floor]", no),
    call_ok(A, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", "[?o isIn rc_box]"], _),
    reply_case(A, 'own watcher on another predicate', Samples,
               "[rc_pred_~d hasColor red]", no),
    call_ok(A, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", "[?o isOn rc_table]"], Id),
    reply_case(A, 'own watcher on the predicate, not firing', Samples,
               "[rc_quiet_~d isOn floor]", no),
    reply_case(A, 'own watcher firing (until reply and event read)', Samples,
               "[rc_fire_~d isOn rc_table]", Id).

%   reply_case(+Conn, +Name, +Samples, +Format, +Event): time Samples
%   adds of format(Format, [I]); Event is `no`, or the watcher id whose
%   event must follow each reply.

reply_case(Conn, Name, Samples, Format, Event) :-
    findall(T,
            ( between(1, Samples, I),
              format(string(Stmt), Format, [I]),
              reply_sample(Conn, Stmt, Event, T)
            ), Times),
    length(Times, N),
    (   N =:= Samples
    ->  bench_summary(Times, Median, P99),
        bench_micros(Median, M),
        bench_micros(P99, P)
    ;   M = failed,
        P = '-'
    ),
    format("~w~t~56|~w~t~14+~w~n", [Name, M, P]),
    flush_output.

reply_sample(Conn, Stmt, Event, T) :-
    get_time(T0),
    bench_send(Conn, add, [Stmt]),
    bench_receive(Conn, ok(_), 30),
    (   Event == no
    ->  true
    ;   bench_receive(Conn, event(Event, _), 5)
    ),
    get_time(T1),
    T is (T1 - T0) * 1.0e6.

		 /*******************************
		 *             HOPS             *
		 *******************************/

%   hops(+World, +Samples): the same world and watchers in this process,
%   one subscriber whose delivery thread stamps each event.

hops(World, Samples) :-
    oro_init([]),
    bench_world(World, Texts),
    bench_batches(Texts, 100, Batches),
    forall(member(B, Batches), oro_add(myself, B)),
    issue_classes(Classes),
    oro_add(myself, Classes),
    issue_watchers(Watchers),
    message_queue_create(Q),
    oro_subscriber_create(stamp(Q), Subscriber, []),
    findall(N-Id,
            ( member(w(N, Pattern, _), Watchers),
              oro_register_event(myself, new_instance, on_true, x, [Pattern],
                                 Subscriber, Id)
            ), Registered),
    hop_samples(Samples, Registered, Watchers, Q, Rows),
    thread_hop(Samples, Hop),
    oro_subscriber_destroy(Subscriber),
    message_queue_destroy(Q),
    format("~nHops of one event, in process (same world and watchers)~n", []),
    format("~w~t~56|~w~t~14+~w~n", [step, median, p99]),
    forall(member(Name-Times, [ 'writer: add, no watcher concerned'-Unwatched,
                                'writer: add firing one watcher'-Writer,
                                'one thread-to-thread message'-Hop,
                                'add until the watcher thread is done (sync)'-Synced,
                                'add until the delivery thread has it'-Delivered
                              ]),
           ( Rows = rows(Unwatched, Writer, Synced, Delivered),
             bench_summary(Times, Median, P99),
             bench_micros(Median, M),
             bench_micros(P99, P),
             format("~w~t~56|~w~t~14+~w~n", [Name, M, P])
           )),
    flush_output.

stamp(Q, Id, Content) :-
    get_time(T),
    thread_send_message(Q, delivered(Id, Content, T)).

%   hop_samples(+Samples, +Registered, +Watchers, +Q, -Rows): per
%   sample, an add on a predicate no watcher uses; an add firing one
%   watcher, timed until it returns and until its event is delivered;
%   and an add firing one watcher followed by oro_events_sync/0.

hop_samples(Samples, Registered, Watchers, Q, rows(Unwatched, Writer, Synced, Delivered)) :-
    findall(s(U, W, D, S),
            ( between(1, Samples, I),
              hop_sample(I, Registered, Watchers, Q, U, W, D, S)
            ), Rows),
    findall(U, member(s(U, _, _, _), Rows), Unwatched),
    findall(W, member(s(_, W, _, _), Rows), Writer),
    findall(D, member(s(_, _, D, _), Rows), Delivered),
    findall(S, member(s(_, _, _, S), Rows), Synced).

hop_sample(I, Registered, Watchers, Q, U, W, D, S) :-
    format(string(Plain), "hop_plain_~d hasColor red", [I]),
    bench_time(oro_add(myself, [Plain]), U),
    issue_sample(I, N),
    memberchk(N-Id, Registered),
    memberchk(w(N, _, Fire), Watchers),
    format(atom(Obj), "hop_obj_~d", [I]),
    fire_statement(Fire, Obj, Stmt),
    get_time(T0),
    oro_add(myself, [Stmt]),
    get_time(T1),
    thread_get_message(Q, delivered(Id, _, T2)),
    W is (T1 - T0) * 1.0e6,
    D is (T2 - T0) * 1.0e6,
    format(atom(Obj2), "hop_sync_~d", [I]),
    fire_statement(Fire, Obj2, Stmt2),
    get_time(T3),
    oro_add(myself, [Stmt2]),
    oro_events_sync,
    get_time(T4),
    thread_get_message(Q, delivered(Id, _, _)),
    S is (T4 - T3) * 1.0e6.

%   thread_hop(+Samples, -Times): one message to another thread, half
%   the round trip of a ping to a thread that answers.

thread_hop(Samples, Times) :-
    thread_self(Me),
    message_queue_create(In),
    thread_create(pong(In), Pong, []),
    findall(T,
            ( between(1, Samples, _),
              get_time(T0),
              thread_send_message(In, ping(Me)),
              thread_get_message(pong),
              get_time(T1),
              T is (T1 - T0) * 0.5e6
            ), Times),
    thread_send_message(In, stop),
    thread_join(Pong, _),
    message_queue_destroy(In).

pong(In) :-
    thread_get_message(In, Message),
    (   Message = ping(From)
    ->  thread_send_message(From, pong),
        pong(In)
    ;   true
    ).

		 /*******************************
		 *         MANY WATCHERS        *
		 *******************************/

many(N, Samples) :-
    format("~nMany watchers: ~D registrations from one connection~n", [N]),
    format("~w~t~14|~w~t~12+~w~t~12+~w~t~12+~w~t~13+~w~t~12+~w~t~12+\c
            ~w~t~12+~w~t~13+~w~t~12+~w~n",
           [kind, 'first 1k/s', 'last 1k/s', 'joins/s', 'first add',
            'unwatched', 'watched', event, 'clearEvent', clearEvents,
            close]),
    forall(member(Kind, [new_instance, transitive, fact_checking]),
           ( bench_with_server([], Port, _, many_socket(Port, Kind, N, Samples, Row)),
             many_close(Kind, N, Close),
             many_row(Kind, Row, Close)
           )).

%   many_pattern(+Kind, +I, -Pattern), many_predicate(+Kind, -P): the
%   pattern of watcher I, and its predicate (`behind` is transitive).

many_pattern(Kind, I, Pattern) :-
    many_predicate(Kind, P),
    format(string(Pattern), "?o ~w place_~d", [P, I]).

many_predicate(new_instance, isOn).
many_predicate(transitive, behind).
many_predicate(fact_checking, isOn).

many_register(Conn, Kind, I, Id) :-
    many_pattern(Kind, I, P),
    (   Kind == fact_checking
    ->  call_ok(Conn, registerEvent, ["FACT_CHECKING", "ON_TRUE", [P]], Id)
    ;   call_ok(Conn, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", [P]], Id)
    ).

%   many_socket(+Port, +Kind, +N, +Samples, -Row)

many_socket(Port, Kind, N, Samples, row(First, Last, Join, FirstAdd, Unwatched, Watched, Events, ClearOne, ClearAll)) :-
    bench_with_connection(
        Port, Conn,
        ( many_rates(Conn, Kind, N, Rates, Ids),
          Rates = [First|_],
          last(Rates, Last),
          K is min(1000, N),
          bench_time(forall(between(1, K, I), many_register(Conn, Kind, I, _)), TJoin),
          Join is K / (TJoin / 1.0e6),
          bench_time(( call_ok(Conn, add, ["[first_add hasColor red]"]),
                       many_register(Conn, Kind, 1, _)   % after the change
                     ), FirstAdd),
          add_times(Conn, N, unwatched, Samples, Unwatched),
          many_watched(Conn, Kind, Samples, Watched),
          many_events(Conn, Kind, N, Ids, Samples, Events),
          bench_time(forall(member(Id, Ids), call_ok(Conn, clearEvent, [Id])), ClearOne),
          forall(between(1, N, I), many_register(Conn, Kind, I, _)),
          bench_time(call_ok(Conn, clearEvents, []), ClearAll)
        )).

%   many_rates(+Conn, +Kind, +N, -Rates, -Ids): registrations a second,
%   a thousand at a time.

many_rates(Conn, Kind, N, Rates, Ids) :-
    Chunks is (N + 999) // 1000,
    findall(Rate-ChunkIds,
            ( between(1, Chunks, C),
              From is (C - 1) * 1000 + 1,
              To is min(N, C * 1000),
              get_time(T0),
              findall(Id, ( between(From, To, I),
                            many_register(Conn, Kind, I, Id)
                          ), ChunkIds),
              get_time(T1),
              Rate is (To - From + 1) / (T1 - T0)
            ), Pairs),
    pairs_keys_values(Pairs, Rates, IdLists),
    append(IdLists, Ids).

%   many_watched(+Conn, +Kind, +Samples, -Times): an add on the
%   watchers' predicate that fires none of them, timed until the watcher
%   thread has processed it (a registration of a watcher already
%   registered follows it).

many_watched(Conn, Kind, Samples, Times) :-
    many_predicate(Kind, P),
    findall(T, ( between(1, Samples, I),
                 format(string(Stmt), "[plain_~d ~w floor]", [I, P]),
                 bench_time(( call_ok(Conn, add, [Stmt]),
                              many_register(Conn, Kind, 1, _)
                            ), T)
               ), Times).

%   many_events(+Conn, +Kind, +N, +Ids, +Samples, -Latencies): event
%   latencies of NEW_INSTANCE watchers picked in turn among the N.

many_events(Conn, Kind, N, Ids, Samples, Latencies) :-
    Kind \== fact_checking,
    !,
    many_predicate(Kind, P),
    findall(L, ( between(1, Samples, S),
                 I is (S * 337) mod N + 1,
                 nth1(I, Ids, Id),
                 format(atom(Obj), "many_obj_~d", [S]),
                 format(string(Stmt), "[~w ~w place_~d]", [Obj, P, I]),
                 format(string(Expected), "[\"~w\"]", [Obj]),
                 event_latency(Conn, Id, Stmt, Expected, L-_)
               ), Latencies).
many_events(_, _, _, _, _, []).

%   many_close(+Kind, +N, -Micros): in this process, the time to destroy
%   a subscriber of N watchers, as a connection's close does.

many_close(Kind, N, Micros) :-
    oro_init([]),
    oro_subscriber_create(many_ignore, Subscriber, []),
    forall(between(1, N, I),
           ( many_pattern(Kind, I, P),
             (   Kind == fact_checking
             ->  oro_register_event(myself, fact_checking, on_true, '', [P],
                                    Subscriber, _)
             ;   oro_register_event(myself, new_instance, on_true, o, [P],
                                    Subscriber, _)
             )
           )),
    bench_time(oro_subscriber_destroy(Subscriber, [abort(true)]), Micros),
    oro_watchers(myself, []),
    oro_reset.

many_ignore(_, _).

seconds_text(Micros, Text) :-
    format(string(Text), "~3f s", [Micros / 1.0e6]).

many_row(Kind, row(First, Last, Join, FirstAdd, Unwatched, Watched, Events, ClearOne, ClearAll), Close) :-
    bench_micros(FirstAdd, FA),
    median_text(Unwatched, U),
    median_text(Watched, W),
    median_text(Events, E),
    maplist(seconds_text, [ClearOne, ClearAll, Close], [C1, CA, CL]),
    format("~w~t~14|~0f~t~12+~0f~t~12+~0f~t~12+~w~t~13+~w~t~12+~w~t~12+\c
            ~w~t~12+~w~t~13+~w~t~12+~w~n",
           [Kind, First, Last, Join, FA, U, W, E, C1, CA, CL]),
    flush_output.

		 /*******************************
		 *            REPORT            *
		 *******************************/

row(Level, RegTimes, Latencies, AfterOk, Missed, Unwatched, Watched) :-
    median_text(RegTimes, Reg),
    bench_summary(Latencies, LMedian, LP99),
    bench_micros(LMedian, LMed),
    bench_micros(LP99, LP),
    median_text(AfterOk, AMed),
    median_text(Unwatched, UMed),
    median_text(Watched, WMed),
    (   Level = W-other
    ->  format(string(Label), "~d (isIn)", [W])
    ;   format(string(Label), "~d", [Level])
    ),
    format("~w~t~12|~w~t~12+~w~t~14+~w~t~14+~w~t~14+~w~t~8+~w~t~15+~w~n",
           [Label, Reg, LMed, LP, AMed, Missed, UMed, WMed]),
    flush_output.

%   median_text(+Times, -Text): the median of Times, "-" if there are
%   none.

median_text(Times, Text) :-
    bench_summary(Times, Median, _),
    bench_micros(Median, Text).
