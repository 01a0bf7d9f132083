/*  Durability costs: swipl bench/bench_durability.pl [--updates=N] [--batch=N]

    In process, with and without a database directory (oro_init/1's
    db(Dir)):

      - add 1 statement, and a batch of 100, per second;
      - N updates (default 1,000,000) of a functional property of the
        same 5 facts, then the bytes on disk (journals, snapshots,
        commit log): compaction keeps it bounded;
      - the time to restore the directory (oro_init/1 on it).
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
:- use_module('../prolog/oro/oro_persist').

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(updates(Updates), Options, 1000000),
    bench_machine,
    format("~n| measure | in memory | with --db |~n|---|---|---|~n"),
    rate_row('add 1 statement', 2000, 1),
    rate_row('add a batch of 100', 200, 100),
    tmp_file(oro_bench_db, Dir),
    call_cleanup(updates(Dir, Updates),
                 ( oro_close,
                   delete_directory_and_contents(Dir) )).

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
