/*  Durability costs: swipl bench/bench_durability.pl [--updates=N]
                      [--live=100000,1000000] [--shrink=500000]
                      [--churn=500000] [--runs=3]

    In process, with and without a database directory (oro_init/1's
    db(Dir)):

      - add 1 statement, and a batch of 100, per second;
      - N updates (default 1,000,000) of a functional property of the
        same 5 facts, then the bytes on disk (journals, snapshots,
        commit log): compaction keeps it bounded;
      - the time to restore the directory (oro_init/1 on it).

    Restart time against the live triples (`--live`, `--shrink`,
    `--churn`; 0 skips): for each size L of `--live`, a directory
    holding L triples (`obj_I isOn table_J`) added in changes of 1,000;
    with `--shrink=C`, one holding C/5 triples left by C triples changed
    in changes of 1,000 (3/5 of them adds, 2/5 removes: the store grows
    to 300,000 at C = 500,000, then shrinks); with `--churn=C`, the same
    in C changes of one statement each.  Each is restarted in a
    fresh process (swipl, then oro_init/1 with db(Dir), no common-sense
    ontology), against the same triples written as N-Triples and loaded
    in a fresh process, as an ontology (oro_init/1 with ontologies([File]))
    and bare (rdf_load/2 into a graph): wall time of the load alone,
    the process's start excluded, the best of `--runs` (default 3)
    taken in turn.  Also the bytes on disk, and the
    longest change while the directory was filled (a change that
    compacts a journal writes a snapshot of the live triples).
*/

:- initialization(main, main).

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(filesex)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(bench_common).
:- use_module(library(process)).
:- use_module(library(aggregate)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/oro_persist)).
:- use_module(library(oro/oro_store), [oro_graph/3]).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(updates(Updates), Options, 1000000),
    bench_list_option(live(Lives0), Options, [100000, 1000000]),
    exclude(==(0), Lives0, Lives),
    option(shrink(Shrink), Options, 500000),
    option(churn(Churn), Options, 500000),
    findall(H, ( member(L, Lives), H = bulk(L)
               ; Shrink > 0, H = shrink(Shrink)
               ; Churn > 0, H = churn(Churn)
               ), Histories),
    (   option(restore(RestoreDir), Options)
    ->  restore_child(RestoreDir, Options)
    ;   main(Updates, Histories)
    ).

main(Updates, Histories) :-
    bench_machine,
    format("~n| measure | in memory | with --db |~n|---|---|---|~n"),
    rate_row('add 1 statement', 2000, 1),
    rate_row('add a batch of 100', 200, 100),
    tmp_file(oro_bench_db, Dir),
    call_cleanup(updates(Dir, Updates),
                 ( oro_close,
                   delete_directory_and_contents(Dir) )),
    restarts(Histories).

%   rate_row(+Label, +Requests, +BatchSize): statements per second.

rate_row(Label, Requests, Size) :-
    rate(none, Requests, Size, Memory),
    tmp_file(oro_bench_db, Dir),
    call_cleanup(rate(Dir, Requests, Size, Disk),
                 ( oro_close,
                   delete_directory_and_contents(Dir) )),
    format("| ~w | ~0f stmt/s | ~0f stmt/s |~n", [Label, Memory, Disk]).

rate(Dir, Requests, Size, Rate) :-
    (   Dir == none
    ->  oro_init([commonsense(false)])
    ;   oro_init([commonsense(false), db(Dir)])
    ),
    numlist(1, Requests, Rs),
    numlist(1, Size, Is),
    get_time(T0),
    forall(member(R, Rs),
           ( maplist(statement(R), Is, Statements),
             oro_add(myself, Statements)
           )),
    get_time(T1),
    Rate is Requests * Size / (T1 - T0).

statement(R, I, S) :-
    format(string(S), "obj_~d_~d isOn table_~d", [R, I, I]).

updates(Dir, N) :-
    oro_init([commonsense(false), db(Dir)]),
    oro_add(myself, ["hasCharge rdf:type owl:FunctionalProperty"]),
    get_time(T0),
    forall(between(1, N, I),
           ( K is I mod 5,
             format(string(S), "robot_~d hasCharge ~d", [K, I]),
             oro_update(myself, [S])
           )),
    get_time(T1),
    oro_persist_sizes(Sizes),
    oro_close,
    get_time(T2),
    oro_init([commonsense(false), db(Dir)]),
    get_time(T3),
    Rate is N / (T1 - T0),
    Restore is (T3 - T2) * 1000,
    format("~n~D updates of 5 facts with --db: ~0f updates/s~n", [N, Rate]),
    format("on disk after them: ~D bytes (journals ~D, snapshots ~D, \c
            commit log ~D)~n",
           [Sizes.total, Sizes.journals, Sizes.snapshots, Sizes.commit_log]),
    format("restore (oro_init on the directory): ~1f ms~n", [Restore]).

		 /*******************************
		 *      RESTART AGAINST LIVE    *
		 *******************************/

restarts([]) :-
    !.
restarts(Histories) :-
    format("~n| live triples | history | on disk | longest change | \c
            restart with --db | N-Triples as ontology | N-Triples bare |~n\c
            |---|---|---|---|---|---|---|~n"),
    forall(member(History, Histories), restart_row(History)).

restart_row(History) :-
    tmp_file(oro_bench_db, Dir),
    tmp_file(oro_bench_nt, Base),
    file_name_extension(Base, nt, NT),
    call_cleanup(restart_measure(History, Dir, NT),
                 ( oro_close,
                   delete_directory_and_contents(Dir),
                   (   exists_file(NT)
                   ->  delete_file(NT)
                   ;   true
                   ) )).

restart_measure(History, Dir, NT) :-
    oro_init([commonsense(false), db(Dir)]),
    fill(History, Longest),
    oro_persist_sizes(Sizes),
    live_ntriples(NT, Live),
    oro_close,
    best_restore_times([db(Dir), ontology(NT), bare(NT)], Live,
                       [DbTime, OntoTime, BareTime]),
    history_text(History, Text),
    format("| ~D | ~w | ~1f MB (journals ~1f, snapshots ~1f) | ~0f ms | \c
            ~2f s | ~2f s | ~2f s |~n",
           [Live, Text, Sizes.total / 1.0e6, Sizes.journals / 1.0e6,
            Sizes.snapshots / 1.0e6, Longest * 1000, DbTime, OntoTime,
            BareTime]),
    flush_output.

history_text(bulk(L), Text) :-
    Changes is L // 1000,
    format(string(Text), "~D adds of 1,000", [Changes]).
history_text(shrink(C), Text) :-
    Changes is C // 1000,
    format(string(Text), "~D adds and removes of 1,000", [Changes]).
history_text(churn(C), Text) :-
    format(string(Text), "~D changes of 1", [C]).

%   fill(+History, -Longest): make the changes of History; Longest is
%   the longest one, in seconds.

fill(bulk(L), Longest) :-
    Changes is L // 1000,
    fill_changes(Changes, bulk_change, Longest).
fill(shrink(C), Longest) :-
    Changes is C // 1000,
    fill_changes(Changes, shrink_change(Changes), Longest).
fill(churn(C), Longest) :-
    fill_changes(C, churn_change(C), Longest).

fill_changes(N, Change, Longest) :-
    nb_setval(bench_longest, 0),
    forall(between(1, N, I),
           ( get_time(T0),
             call(Change, I),
             get_time(T1),
             T is T1 - T0,
             nb_getval(bench_longest, M0),
             (   T > M0
             ->  nb_setval(bench_longest, T)
             ;   true
             )
           )),
    nb_getval(bench_longest, Longest).

bulk_change(I) :-
    findall(S, ( between(1, 1000, J),
                 K is (I - 1) * 1000 + J,
                 object_statement(K, S)
               ), Statements),
    oro_add(myself, Statements).

%   shrink_change(+C, +I): change I of C, of 1,000 statements: the first
%   3/5 add, the rest remove from the first on.

shrink_change(C, I) :-
    Adds is C * 3 // 5,
    (   I =< Adds
    ->  bulk_change(I)
    ;   K is I - Adds,
        findall(S, ( between(1, 1000, J),
                     N is (K - 1) * 1000 + J,
                     object_statement(N, S)
                   ), Statements),
        oro_remove(myself, Statements)
    ).

%   churn_change(+C, +I): change I of C: the first 3/5 add object I,
%   the rest remove the objects from 1 on, leaving C/5 of them.

churn_change(C, I) :-
    Adds is C * 3 // 5,
    (   I =< Adds
    ->  object_statement(I, S),
        oro_add(myself, [S])
    ;   K is I - Adds,
        object_statement(K, S),
        oro_remove(myself, [S])
    ).

object_statement(K, S) :-
    T is K mod 997,
    format(string(S), "obj_~d isOn table_~d", [K, T]).

%   live_ntriples(+File, -Count): write the triples of the robot's model
%   to File as N-Triples (they are all IRIs).

live_ntriples(File, Count) :-
    setup_call_cleanup(
        open(File, write, Out, [encoding(utf8)]),
        aggregate_all(count,
                      ( oro_model_triple(S, P, O),
                        format(Out, "<~w> <~w> <~w> .~n", [S, P, O])
                      ),
                      Count),
        close(Out)).

oro_model_triple(S, P, O) :-
    oro_graph(myself, profile(longterm), G),
    rdf(S, P, O, G).

%   best_restore_times(+Whats, +Live, -Seconds): the shortest of
%   `--runs` (default 3) restore times of each of Whats, measured in
%   turn (a busy machine slows some runs down).

best_restore_times(Whats, Live, Best) :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(runs(Runs), Options, 3),
    findall(Times, ( between(1, Runs, _),
                     maplist(restore_time_of(Live), Whats, Times)
                   ), Rows),
    transpose_rows(Rows, Columns),
    maplist(min_list, Columns, Best).

restore_time_of(Live, What, Seconds) :-
    restore_time(What, Live, Seconds).

transpose_rows([Row|Rows], Columns) :-
    (   Row == []
    ->  Columns = []
    ;   maplist([[H|T], H, T]>>true, [Row|Rows], Heads, Tails),
        Columns = [Heads|Columns1],
        transpose_rows(Tails, Columns1)
    ).

%   restore_time(+What, +Live, -Seconds): wall time to load What in a
%   fresh process (this script with --restore), checking it holds Live
%   triples.

restore_time(What, Live, Seconds) :-
    What =.. [Kind, Path],
    source_file(main, Script),
    format(atom(A1), "--restore=~w", [Path]),
    format(atom(A2), "--kind=~w", [Kind]),
    process_create(path(swipl), [Script, A1, A2],
                   [stdout(pipe(Out)), process(Pid)]),
    call_cleanup(read_term(Out, Result, []), close(Out)),
    process_wait(Pid, _),
    (   Result = restored(Seconds, Triples),
        Triples >= Live
    ->  true
    ;   throw(error(bench_restore_failed(What, Result), _))
    ).

restore_child(Path, Options) :-
    option(kind(Kind), Options),
    get_time(T0),
    restore(Kind, Path),
    get_time(T1),
    rdf_statistics(triples(N)),
    T is T1 - T0,
    format("~q.~n", [restored(T, N)]),
    halt(0).

restore(db, Dir) :-
    oro_init([commonsense(false), db(Dir)]).
restore(ontology, File) :-
    oro_init([commonsense(false), ontologies([File])]).
restore(bare, File) :-
    rdf_load(File, [graph(bench), format(ntriples), silent(true)]).
