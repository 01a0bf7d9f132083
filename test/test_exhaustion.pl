:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module(library(oro)).
:- use_module('../server/oro_server').

/*  Resource exhaustion and limits (issue #8), over real sockets on
    127.0.0.1 against the in-process server:

      - short-lived values: statements on fresh literals (or fresh
        names) added then removed; after garbage_collect_atoms/0 the
        process's atom count must come back near where it was, and its
        memory must not grow with the number of values (for names,
        the store is rebuilt to empty rdf_db's resource table: see
        test names).
        200,000 names by default, 10,000,000 with ORO_LONG_TESTS=1;
        fresh literals: 50,000, or 250,000;
      - a client that registered an event and never reads: the events
        pushed to it fill its socket, and it must be disconnected
        (write_timeout, lowered to 1 s) while the others are served;
      - clients that open connections and send nothing: others are
        still served up to max_connections (lowered to 8), connections
        beyond it get an error and are closed, and with idle_timeout
        the silent ones are closed so that the server is usable again;
      - limits: max_request_size (exact, and its 16 MiB default),
        max_params (its 4096 default), the per-query time limit
        (oro_query:time_limit) for SPARQL, for the parsing of a query
        and for `find`, while other clients are served.

    Settings are lowered with set_setting/2 for a test and restored
    to their defaults (restore_setting/1) afterwards.  Waits are on
    conditions, with bounds.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_exhaustion.pl
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(settings)).
:- use_module(library(readutil)).
:- use_module(library(semweb/rdf_db)).

exh_long :-
    getenv('ORO_LONG_TESTS', '1').

exh_connect(Conn) :-
    test_server_port(Port),
    oro_connect(Port, Conn, [nodelay(true)]).

%   exh_rss(-KB): the resident memory of this process (Linux), 0 if
%   unknown.

exh_rss(KB) :-
    catch(setup_call_cleanup(
              open('/proc/self/status', read, In),
              exh_vmrss(In, KB),
              close(In)),
          _, KB = 0).

exh_vmrss(In, KB) :-
    read_line_to_string(In, Line),
    (   Line == end_of_file
    ->  KB = 0
    ;   split_string(Line, ":", " \t", ["VmRSS", Value]),
        split_string(Value, " ", "", [Number|_]),
        number_string(KB, Number)
    ->  true
    ;   exh_vmrss(In, KB)
    ).

%   exh_threads(-Threads): the running threads without an alias
%   (connection workers, event delivery threads; library and system
%   threads, some started on first need, have one).
%   exh_new_threads(+Before, -Threads): those not in Before.

exh_threads(Threads) :-
    findall(T, ( thread_property(T, status(running)),
                 \+ thread_property(T, alias(_))
               ),
            Threads).

exh_new_threads(Before, New) :-
    exh_threads(Now),
    exclude(exh_member(Before), Now, New).

exh_member(List, X) :-
    memberchk(X, List).

exh_no_new_threads(Before) :-
    exh_new_threads(Before, []).

%   exh_dropped(+Before): the server serves no connection, and the
%   threads it made since Before (event delivery) have ended.

exh_dropped(Before) :-
    test_server_connections(0),
    exh_no_new_threads(Before).


                 /*******************************
                 *      SHORT-LIVED VALUES      *
                 *******************************/

exh_names(Names) :-
    (   exh_long
    ->  Names = 10000000
    ;   Names = 200000
    ).

%   exh_batch_text(+Kind, +Round, +From, +To, -Set): the statements
%   From..To of a round, written without creating atoms in this
%   process: `exn_R_K exp exo_R_K` (two fresh names each) or
%   `exl_J exp "R value K"` (a fresh literal each, on 1000 subjects
%   that are always the same: J is K mod 1000, so that no subject has
%   more than one value at a time).

exh_batch_text(Kind, Round, From, To, Set) :-
    with_output_to(string(Set),
                   ( write('['),
                     forall(between(From, To, K),
                            ( (   K > From
                              ->  write(', ')
                              ;   true
                              ),
                              exh_statement(Kind, Round, K)
                            )),
                     write(']')
                   )).

exh_statement(names, Round, K) :-
    format("exn_~d_~d exp exo_~d_~d", [Round, K, Round, K]).
exh_statement(literals, Round, K) :-
    J is K mod 1000,
    format("exl_~d exp \"~d value ~d\"", [J, Round, K]).

%   exh_round(+Conn, +Kind, +Round, +Statements, +RssLimit, -Result):
%   add then remove Statements fresh statements, 1000 per request (the
%   add and the remove of a batch pipelined).  Result is `done`, or
%   stopped(K, Reply) on an unexpected reply, or grew(KB, K) if the
%   process grew past RssLimit KB.

exh_round(Conn, Kind, Round, Statements, RssLimit, Result) :-
    exh_round(Conn, Kind, Round, 0, Statements, RssLimit, Result).

exh_round(Conn, Kind, Round, From, Statements, RssLimit, Result) :-
    (   From >= Statements
    ->  Result = done
    ;   To is min(Statements, From + 1000) - 1,
        exh_batch_text(Kind, Round, From, To, Set),
        oro_send(Conn, add, [Set]),
        oro_send(Conn, remove, [Set]),
        oro_receive(Conn, Added, 60),
        oro_receive(Conn, Removed, 60),
        (   Added-Removed \== ok("")-ok("")
        ->  Result = stopped(From, Added-Removed)
        ;   From mod 100000 =:= 0,
            exh_rss(KB),
            KB > RssLimit
        ->  Result = grew(KB, From)
        ;   Next is To + 1,
            exh_round(Conn, Kind, Round, Next, Statements, RssLimit, Result)
        )
    ).

%   exh_measure(-Atoms, -Resources, -RssKB) after atom garbage
%   collection (and rdf_db's).

exh_measure(Atoms, Resources, RssKB) :-
    rdf_gc,
    garbage_collect_clauses,
    garbage_collect_atoms,
    garbage_collect_atoms,
    statistics(atoms, Atoms),
    rdf_statistics(resources(Resources)),
    exh_rss(RssKB).

%   exh_short_lived(+Kind, +Values, -Outcome): Values fresh values (one
%   per statement) added and removed in one round, after a
%   warm-up round.  Outcome is `ok`, or a term with the figures.  At
%   most 1/50 of the values (and 2000 atoms) may be left, and the
%   process may not grow by more than 64 MB plus 16 bytes per value.

exh_short_lived(Kind, Values, Outcome) :-
    exh_connect(Conn),
    call_cleanup(exh_short_lived(Conn, Kind, Values, Values, Outcome),
                 oro_disconnect(Conn)).

exh_short_lived(Conn, Kind, Values, Statements, Outcome) :-
    exh_round(Conn, Kind, 0, 2000, inf, Warm),
    exh_measure(A0, R0, KB0),
    RssLimit is KB0 + 1048576,
    exh_round(Conn, Kind, 1, Statements, RssLimit, Result),
    exh_measure(A1, R1, KB1),
    Atoms is A1 - A0,
    Resources is R1 - R0,
    Growth is KB1 - KB0,
    MaxAtoms is max(2000, Values // 50),
    MaxGrowth is 65536 + (Values * 16) // 1024,
    (   Warm == done,
        Result == done,
        Atoms =< MaxAtoms,
        Growth =< MaxGrowth
    ->  Outcome = ok
    ;   Outcome = left(Kind, values(Values), round(Result),
                       atoms(Atoms), rdf_resources(Resources),
                       rss_growth_kb(Growth))
    ).

:- begin_tests(exhaustion_short_lived,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

%   Fresh literals (50,000; 250,000 with ORO_LONG_TESTS=1): rdf_db
%   frees them, and so does oro.

test(literals, [true(Outcome == ok)]) :-
    exh_names(Names),
    Values is min(Names // 4, 250000),
    exh_short_lived(literals, Values, Outcome).

%   Fresh names (IRIs): SWI-Prolog 9.0.4's rdf_db keeps every resource
%   it ever saw in its resource table (its atom and about 150 bytes)
%   until rdf_reset_db/0, so the server rebuilds the store once the
%   table holds rebuild_garbage names more than after the last rebuild
%   (lowered to 20,000 here, from 1,000,000).  Afterwards, as for
%   literals, the atoms must be back near where they were (at most
%   2000, or 1/50 of the names, more), rdf_db's table may hold no more
%   than the allowance, and the process may grow by at most 64 MB:
%   nothing in proportion to the number of names.

exh_names_garbage(20000).

test(names, [true(Outcome == ok)]) :-
    exh_names(Names),
    exh_names_garbage(Garbage),
    exh_connect(Conn),
    call_cleanup(test_with_setting(oro_store:rebuild_garbage, Garbage,
                                  exh_names_kept(Conn, Names, Outcome)),
                 oro_disconnect(Conn)).

exh_names_kept(Conn, Names, Outcome) :-
    exh_names_garbage(Garbage),
    Statements is Names // 2,
    exh_round(Conn, names, 0, 2000, inf, Warm),
    exh_measure(A0, R0, KB0),
    RssLimit is KB0 + 1048576,
    exh_round(Conn, names, 1, Statements, RssLimit, Result),
    exh_measure(A1, R1, KB1),
    Atoms is A1 - A0,
    Resources is R1 - R0,
    Growth is KB1 - KB0,
    MaxAtoms is max(2000, Names // 50) + Garbage,
    (   Warm == done,
        Result == done,
        Atoms =< MaxAtoms,
        Resources =< Garbage + R0,
        Growth =< 65536
    ->  Outcome = ok
    ;   Outcome = left(names, values(Names), round(Result),
                       atoms(Atoms), rdf_resources(Resources),
                       rss_growth_kb(Growth))
    ).

:- end_tests(exhaustion_short_lived).


                 /*******************************
                 *     A CLIENT THAT NEVER READS *
                 *******************************/

%   A client registers a NEW_INSTANCE watcher that fires on every batch
%   another client adds or removes, then neither reads nor sends.  The
%   events (8 MB in all, ten times what the socket buffers took in a
%   trial) must not hold the server: the other client is served all
%   along, and the silent one is disconnected (the server serves no
%   connection any more, and the event delivery thread it made has
%   ended) within 10 s, ten times the write timeout (lowered to 1 s).

exh_event_names(200).                   % instances per batch
exh_event_batches(100).                 % each added then removed

exh_event_batch(Round, Set) :-
    exh_event_names(N),
    Last is N - 1,
    exh_repeat(180, x, Long),           % long names: 40 KB per event
    with_output_to(string(Set),
                   ( write('['),
                     forall(between(0, Last, K),
                            ( (   K > 0
                              ->  write(', ')
                              ;   true
                              ),
                              format("exe_~d_~d_~w exep exeo", [Round, K, Long])
                            )),
                     write(']')
                   )).

%   exh_event_load(+Conn, -Outcome): the other client's batches, each
%   answered within 10 s; Outcome is `served` or the first bad reply.

exh_event_load(Conn, Outcome) :-
    exh_event_batches(Batches),
    exh_event_load(Conn, 1, Batches, Outcome).

exh_event_load(Conn, Round, Batches, Outcome) :-
    (   Round > Batches
    ->  Outcome = served
    ;   exh_event_batch(Round, Set),
        oro_call(Conn, add, [Set], Added, 10),
        oro_call(Conn, remove, [Set], Removed, 10),
        (   Added-Removed == ok("")-ok("")
        ->  Next is Round + 1,
            exh_event_load(Conn, Next, Batches, Outcome)
        ;   Outcome = not_served(Round, Added-Removed)
        )
    ).

:- begin_tests(exhaustion_non_reader,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

test(events_to_a_client_that_never_reads,
     [ true(Served-Dropped == served-dropped) ]) :-
    exh_threads(Before),
    test_with_setting(
        oro_server:write_timeout, 1,
        ( exh_connect(Silent),
          call_cleanup(
              ( oro_call(Silent, registerEvent,
                         ["NEW_INSTANCE", "ON_TOGGLE", "x", "[?x exep exeo]"],
                         ok(_)),
                exh_connect(Other),
                call_cleanup(exh_event_load(Other, Served),
                             oro_disconnect(Other)),
                (   test_wait_until(exh_dropped(Before), 10)
                ->  Dropped = dropped
                ;   exh_new_threads(Before, Left),
                    length(Left, N),
                    Dropped = still_connected(threads(N))
                )
              ),
              oro_disconnect(Silent))
        )),
    ignore(test_wait_until(exh_no_new_threads(Before), 30)).

:- end_tests(exhaustion_non_reader).


                 /*******************************
                 *   CONNECTIONS, IDLE CLIENTS  *
                 *******************************/

exh_max_connections(8).

exh_start_limited :-
    exh_max_connections(Max),
    set_setting(oro_server:max_connections, Max),
    test_server_start_testsuite.

exh_stop_limited :-
    test_server_stop,
    restore_setting(oro_server:max_connections).

%   exh_open(+N, -Conns): N connections that send nothing.

exh_open(N, Conns) :-
    length(Conns, N),
    maplist(exh_connect, Conns).

exh_close_all(Conns) :-
    maplist(oro_disconnect, Conns).

%   exh_silence(+Conn, -Kind): `silent` if Conn received nothing in
%   0.5 s, else what it received (`refused` for an error then the
%   connection closed).

exh_silence(Conn, Kind) :-
    oro_receive(Conn, Message, 0.5),
    (   Message == timeout
    ->  Kind = silent
    ;   Message = error(_, Text),
        sub_string(Text, _, _, _, "Too many connections"),
        oro_drain(Conn, [end_of_file], 10)
    ->  Kind = refused
    ;   Kind = Message
    ).

exh_refusal(Conn, Kind) :-
    oro_receive(Conn, Message, 10),
    (   Message = error(_, Text),
        sub_string(Text, _, _, _, "Too many connections"),
        oro_drain(Conn, [end_of_file], 10)
    ->  Kind = refused
    ;   Kind = Message
    ).

exh_served(Reply) :-
    exh_connect(Conn),
    call_cleanup(oro_call(Conn, check, ["[baboon rdf:type Animal]"], Reply, 10),
                 oro_disconnect(Conn)).

exh_served_now :-
    catch(exh_served(ok("true")), _, fail).

:- begin_tests(exhaustion_connections,
               [ setup(exh_start_limited),
                 cleanup(exh_stop_limited)
               ]).

%   6 silent clients, then one that works: served.  One more silent
%   one fills the pool; the next 2 are refused with an error and closed.
%   The working client is still served; once the silent ones leave, a
%   new client is served again.

test(silent_clients,
     [ true(Served-Kinds-Still-Again ==
            ok("true")-[silent, refused, refused]-ok("true")-true) ]) :-
    exh_open(6, Silent),
    exh_connect(Worker),
    call_cleanup(
        ( oro_call(Worker, check, ["[baboon rdf:type Animal]"], Served, 10),
          exh_open(1, More),
          exh_open(2, Extra),
          maplist(exh_silence, More, Kinds1),
          maplist(exh_refusal, Extra, Kinds2),
          append(Kinds1, Kinds2, Kinds),
          oro_call(Worker, check, ["[baboon rdf:type Animal]"], Still, 10),
          exh_close_all(More),
          exh_close_all(Extra)
        ),
        ( oro_disconnect(Worker),
          exh_close_all(Silent)
        )),
    test_bool(test_wait_until(exh_served_now, 10), Again).

%   With idle_timeout, silent clients holding every connection are
%   told why and closed, and the server is usable again.  (Whether a
%   client is refused meanwhile depends on timing: not tested here.)

test(idle_timeout_frees_the_server, [true(Closed-Again == all-true)]) :-
    exh_max_connections(Max),
    test_wait_until(exh_no_connection, 10),   % the last test's are gone
    test_with_setting(
        oro_server:idle_timeout, 1,
        ( exh_open(Max, Silent),
          call_cleanup(
              ( maplist(exh_idle_closed, Silent, Kinds),
                (   maplist(==(closed), Kinds)
                ->  Closed = all
                ;   Closed = Kinds
                )
              ),
              exh_close_all(Silent))
        )),
    test_bool(test_wait_until(exh_served_now, 10), Again).

exh_no_connection :-
    \+ oro_server:connection(_).

exh_idle_closed(Conn, Kind) :-
    oro_drain(Conn, Messages, 15),
    (   Messages = [error(_, Text), end_of_file],
        sub_string(Text, _, _, _, "No request")
    ->  Kind = closed
    ;   Kind = Messages
    ).

:- end_tests(exhaustion_connections).

%   Connection workers: `spare_workers` (lowered to 2) threads wait for
%   clients from the start, so connecting makes no thread; connections
%   beyond them get threads of their own, which end with them, while
%   the spare ones are kept.

exh_start_workers :-
    set_setting(oro_server:spare_workers, 2),
    exh_start_limited.

exh_stop_workers :-
    exh_stop_limited,
    restore_setting(oro_server:spare_workers).

exh_thread_count(N) :-
    aggregate_all(count, thread_property(_, status(running)), N).

exh_served_on(Conn) :-
    oro_call(Conn, check, ["[baboon rdf:type Animal]"], ok("true"), 10).

:- begin_tests(exhaustion_workers,
               [ setup(exh_start_workers),
                 cleanup(exh_stop_workers)
               ]).

test(connecting_makes_no_thread, [true(During == Before)]) :-
    once(exh_served_now),               % the server's threads are all up
    once(test_wait_until(test_server_connections(0), 10)),
    exh_threads(Before),
    exh_connect(Conn),
    call_cleanup(( exh_served_on(Conn),
                   exh_threads(During)
                 ),
                 oro_disconnect(Conn)).

test(spare_workers_kept, [true(Got == [5, 5, 3, true, true])]) :-
    once(test_wait_until(test_server_connections(0), 10)),
    exh_thread_count(Before),
    exh_open(5, Conns),
    call_cleanup(( include(exh_served_on, Conns, Served),
                   length(Served, NServed),
                   test_server_connections(Busy),
                   exh_thread_count(During),
                   NNew is During - Before
                 ),
                 exh_close_all(Conns)),
    % the spare workers that wait again need not be the first ones
    test_bool(test_wait_until(exh_thread_count(Before), 10), Back),
    test_bool(exh_served_now, Again),
    Got = [NServed, Busy, NNew, Back, Again].

test(a_late_signal_ends_nothing, [true(Got == [none, ended(x), none])]) :-
    setup_call_cleanup(
        nb_setval(oro_server_serving, 2),
        ( catch(oro_server:end_serving(1, x), E1, true),
          catch(oro_server:end_serving(2, x), E2, true),
          catch(oro_server:end_serving(2, x), E3, true)
        ),
        nb_setval(oro_server_serving, none)),
    maplist(exh_thrown, [E1, E2, E3], Got).

%   The count of connections and waiting workers (white box: the
%   predicates the accept thread and the workers call under the mutex
%   oro_server_workers), on a key no server uses; spare_workers is 2.

test(worker_counts,
     [ true(Got == [ waiting-(1-0), new-(2-0), full-(2-0), (1-0),
                     true-(0-1), [waiting, full-(1-stopped), none] ])
     ]) :-
    Jobs = exh_no_server,
    setup_call_cleanup(
        assertz(oro_server:workers(Jobs, 0, 1)),
        ( exh_counts(reserve_worker(Jobs, 2), Got1),
          exh_counts(reserve_worker(Jobs, 2), Got2),
          exh_counts(reserve_worker(Jobs, 2), Got3),
          oro_server:unreserve_worker(Jobs),
          exh_counts(Got4),
          oro_server:release_worker(Jobs, Wait),
          exh_counts(Counts5),
          oro_server:reserve_worker(Jobs, 2, How6),       % a connection
          oro_server:workers_stopped(Jobs),
          exh_counts(reserve_worker(Jobs, 2), Got6),      % none after
          oro_server:release_worker(Jobs, _),             % it ends
          (   oro_server:workers(Jobs, _, _)
          ->  Left = left
          ;   Left = none
          )
        ),
        retractall(oro_server:workers(Jobs, _, _))),
    Got = [Got1, Got2, Got3, Got4, Wait-Counts5, [How6, Got6, Left]].

exh_counts(Goal, How-Counts) :-
    call(oro_server:Goal, How),
    exh_counts(Counts).

exh_counts(Busy-Idle) :-
    oro_server:workers(exh_no_server, Busy, Idle).

%   A worker that served a large request gives its stacks back before
%   it waits again (release_stacks/0 in the server).

test(large_request_stacks_released, [true(Got == [ok, true])]) :-
    once(test_wait_until(test_server_connections(0), 10)),
    exh_large_set(20000, Set),
    exh_connect(Conn),
    call_cleanup(oro_call(Conn, add, [Set], Reply, 60),
                 oro_disconnect(Conn)),
    exh_reply_kind(Reply, Kind),
    test_bool(test_wait_until(exh_small_stacks, 10), Small),
    Got = [Kind, Small].

exh_large_set(N, Set) :-
    numlist(1, N, Is),
    maplist(exh_large_statement, Is, Statements),
    test_set_text(Statements, Set).

exh_large_statement(I, S) :-
    format(string(S), "exl~d exlp exlo~d", [I, I]).

%   exh_small_stacks: no thread without an alias (the workers among
%   them) holds more than 4 MB of stacks, and none serves a client.

exh_small_stacks :-
    test_server_connections(0),
    exh_threads(Threads),
    forall(member(T, Threads),
           ( thread_statistics(T, global, G),
             thread_statistics(T, local, L),
             thread_statistics(T, trail, Tr),
             G + L + Tr =< 4 194 304
           )).

%   A stopped server still serves the connections it had; their workers
%   end with them, and its waiting workers at once.  (A server of its
%   own: starting it initialises the store again.)

test(stop_lets_connections_finish,
     [true(Got == [ok, 1, ok, true, true])]) :-
    oro_server_start([port(0), host('127.0.0.1')], Server),
    oro_server_port(Server, Port),
    exh_thread_count(Started),          % with its accept thread, 2 workers
    Before is Started - 3,
    oro_connect(Port, Conn, [nodelay(true)]),
    call_cleanup(( oro_call(Conn, check, ["[baboon rdf:type Animal]"], Reply0, 10),
                   oro_server_stop(Server),
                   oro_server_connections(Server, Open),
                   oro_call(Conn, check, ["[baboon rdf:type Animal]"], Reply1, 10)
                 ),
                 oro_disconnect(Conn)),
    test_bool(test_wait_until(oro_server_connections(Server, 0), 10), None),
    test_bool(test_wait_until(exh_thread_count(Before), 10), Back),
    maplist(exh_reply_kind, [Reply0, Reply1], [Kind0, Kind1]),
    Got = [Kind0, Open, Kind1, None, Back].

exh_reply_kind(Reply, Kind) :-
    (   Reply = ok(_)
    ->  Kind = ok
    ;   Kind = Reply
    ).

exh_thrown(E, Kind) :-
    (   var(E)
    ->  Kind = none
    ;   E = oro_connection_end(Why)
    ->  Kind = ended(Why)
    ;   Kind = E
    ).

:- end_tests(exhaustion_workers).


                 /*******************************
                 *            LIMITS            *
                 *******************************/

exh_repeat(N, Char, String) :-
    length(Codes, N),
    char_code(Char, Code),
    maplist(=(Code), Codes),
    string_codes(String, Codes).

%   exh_check_request(+Size, -Text): a `check` request of exactly Size
%   bytes, `#end#` included (ASCII).

exh_check_request(Size, Text) :-
    string_length("check\n[exr p \"\"]\n#end#", Fixed),
    N is Size - Fixed,
    exh_repeat(N, x, Filler),
    atomics_to_string(["check\n[exr p \"", Filler, "\"]\n#end#"], Text).

%   exh_sized(+Size, -Replies): send a request of Size bytes, then close
%   our side; Replies is everything until the server closes.

exh_sized(Size, Replies) :-
    exh_check_request(Size, Text),
    exh_connect(Conn),
    call_cleanup(
        ( thread_create(catch(oro_send_data(Conn, [text(Text)]), _, true),
                        Sender, []),
          oro_receive(Conn, First, 60),
          thread_join(Sender, _),
          oro_half_close(Conn),
          oro_drain(Conn, Rest, 60),
          Replies = [First|Rest]
        ),
        oro_disconnect(Conn)).

exh_reply_kinds([], []).
exh_reply_kinds([R|Rs], [K|Ks]) :-
    (   R = ok(_)
    ->  K = ok
    ;   R = error(_, Text),
        sub_string(Text, _, _, _, "larger than")
    ->  K = too_large
    ;   R = error(_, _)
    ->  K = error
    ;   K = R
    ),
    exh_reply_kinds(Rs, Ks).

%   exh_params(+N, -Text): an `add` request with N parameters.

exh_params(N, Text) :-
    length(Lines, N),
    maplist(=("[exq p o]\n"), Lines),
    atomics_to_string(["add\n"|Lines], Head),
    string_concat(Head, "#end#\n", Text).

exh_params_reply(N, Kind) :-
    exh_params(N, Text),
    exh_connect(Conn),
    call_cleanup(
        ( oro_send_data(Conn, [text(Text)]),
          oro_receive(Conn, Reply, 30),
          oro_call(Conn, check, ["[baboon rdf:type Animal]"], After, 10)
        ),
        oro_disconnect(Conn)),
    (   Reply = error(_, Message),
        sub_string(Message, _, _, _, "Too many parameters")
    ->  Kind = too_many-After
    ;   Reply = error(_, Message),
        sub_string(Message, _, _, _, "wrong number of parameters")
    ->  Kind = arity-After
    ;   Kind = Reply-After
    ).

%   A heavy query, its time limit and a client served meanwhile.

exh_time_limit(0.2).

%   exh_timed(+Method, +Params, -Outcome, -OtherServed): send the
%   request on one connection; while it runs, another client is
%   served.  Outcome is `stopped` (a time limit error), or the reply.

exh_timed(Method, Params, Outcome, OtherServed) :-
    exh_time_limit(Limit),
    test_with_setting(
        oro_query:time_limit, Limit,
        ( exh_connect(Conn),
          call_cleanup(
              ( oro_send(Conn, Method, Params),
                exh_served(OtherServed),
                oro_receive(Conn, Reply, 120)
              ),
              oro_disconnect(Conn))
        )),
    (   Reply = error(_, Message),
        sub_string(Message, _, _, _, "time limit")
    ->  Outcome = stopped
    ;   Reply = ok(Value),
        string_length(Value, Len),
        Len > 60
    ->  sub_string(Value, 0, 60, _, Start),
        Outcome = ok(Start)
    ;   Outcome = Reply
    ).

%   exh_grow_store: 150 more statements, so that a join of two unbound
%   patterns costs seconds (2 s in a trial, 10 times the limit).

exh_grow_store :-
    with_output_to(string(Set),
                   ( write('['),
                     forall(between(1, 150, K),
                            ( (   K > 1
                              ->  write(', ')
                              ;   true
                              ),
                              format("ext_~d extp ext_~d", [K, K])
                            )),
                     write(']')
                   )),
    test_ok(add, [Set]).

exh_nested_query(Depth, Query) :-
    exh_repeat(Depth, '{', Open),
    exh_repeat(Depth, '}', Close),
    atomics_to_string(["SELECT ?x WHERE ", Open, " ?x ?p ?o ", Close], Query).

:- begin_tests(exhaustion_limits,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

test(defaults, [true(Defaults == [16777216, 4096, 256, 64, 30, 60, 5, 50000000, 32])]) :-
    maplist(exh_default,
            [ oro_server:max_request_size, oro_server:max_params,
              oro_server:max_connections, oro_server:max_per_address,
              oro_server:idle_timeout, oro_server:write_timeout,
              oro_query:time_limit, oro_parse:inference_limit,
              oro_parse:max_nesting
            ],
            Defaults).

exh_default(Setting, Default) :-
    setting_property(Setting, default(Default)).

%   A request of exactly max_request_size bytes is served; one more
%   byte and it gets an error, then the connection is closed.

test(request_size_exact,
     [ true(At-Over == [ok, end_of_file]-[too_large, end_of_file]) ]) :-
    test_with_setting(oro_server:max_request_size, 4096,
                     ( exh_sized(4096, R1),
                       exh_sized(4097, R2)
                     )),
    exh_reply_kinds(R1, At),
    exh_reply_kinds(R2, Over).

%   The default limit, 16 MiB: a request of 16 MiB + 1 byte is refused
%   (and one of 16 MiB served, with ORO_LONG_TESTS=1).

test(request_size_default, [true(Over == [too_large, end_of_file])]) :-
    setting(oro_server:max_request_size, Max),
    Size is Max + 1,
    exh_sized(Size, R),
    exh_reply_kinds(R, Over).
test(request_size_default_served,
     [ condition(exh_long), true(At == [ok, end_of_file]) ]) :-
    setting(oro_server:max_request_size, Max),
    exh_sized(Max, R),
    exh_reply_kinds(R, At).

%   max_params: 4096 parameters reach the dispatcher (no `add` has
%   that many), 4097 are refused; the connection goes on in both cases.

test(params_default,
     [ true(At-Over == (arity-ok("true"))-(too_many-ok("true"))) ]) :-
    setting(oro_server:max_params, Max),
    Max1 is Max + 1,
    exh_params_reply(Max, At),
    exh_params_reply(Max1, Over).

%   SPARQL over a cross product: stopped by the time limit; another
%   client is served meanwhile.

test(query_time_limit, [true(Outcome-Other == stopped-ok("true"))]) :-
    exh_timed(query, ["x", "SELECT ?x WHERE { ?x ?p ?o . ?a ?b ?c . ?d ?e ?f FILTER(CONCAT(STR(?o), STR(?c), STR(?f)) = 'none') }"],
              Outcome, Other).

%   The parsing of a query is part of it (the parser takes time
%   quadratic in the nesting of groups: 6,000 levels, 12 KB, take 2 s).

test(query_parse_time_limit, [true(Outcome-Other == stopped-ok("true"))]) :-
    exh_nested_query(6000, Query),
    exh_timed(query, ["x", Query], Outcome, Other).

%   find with filters is evaluated by the SPARQL engine: limited.

test(find_filter_time_limit, [true(Outcome-Other == stopped-ok("true"))]) :-
    exh_grow_store,
    exh_timed(find, ["x", "[?x ?p ?o, ?a ?b ?c]", "[STR(?o) = STR(?c)]"],
              Outcome, Other).

%   find without filters joins three patterns on one unbound predicate
%   (seconds of work): a plain find of several patterns is limited like
%   SPARQL queries.  (Patterns sharing no variable with the one asked
%   for are only checked once: they would cost nothing.)

test(find_time_limit, [true(Outcome-Other == stopped-ok("true"))]) :-
    exh_grow_store,
    exh_timed(find, ["x", "[?x ?p ?o, ?a ?p ?c, ?d ?p ?e]"], Outcome, Other).

:- end_tests(exhaustion_limits).
