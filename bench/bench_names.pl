/*  Memory with short-lived names:
        swipl bench/bench_names.pl [--names=N] [--rebuild-garbage=N]
                                   [--triples=N]

    The real server (a child process) is sent N distinct new names
    (default 10,000,000) by one connection: batches of 500 statements
    `nR_K p oR_K`, each added then removed.  Every million names the
    table gives the server's resident memory and the time so far; the
    server is started with --rebuild-garbage (default: its own default)
    so that the rebuilds keep rdf_db's resource table bounded.  Then
    the time of a rebuild in process, without and with a database
    directory, at 100,000 and 1,000,000 triples (--triples=...) of
    bench_world/2, and what the rebuild's gate costs a call.
*/

:- initialization(main, main).

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(filesex)).
:- use_module(library(semweb/rdf_db)).
:- use_module(bench_common).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(names(Names), Options, 10000000),
    (   option(rebuild_garbage(Garbage), Options)
    ->  format(atom(Arg), '--rebuild-garbage=~d', [Garbage]),
        Args = [Arg]
    ;   Args = []
    ),
    bench_list_option(triples(Sizes), Options, [100000, 1000000]),
    bench_machine,
    format("~n| names | server RSS | seconds |~n|---|---|---|~n"),
    bench_with_server(Args, Port, Pid,
                      bench_with_connection(Port, Conn,
                                            churn(Conn, Pid, Names))),
    format("~n| triples | rebuild in memory | with --db |~n|---|---|---|~n"),
    forall(member(Size, Sizes), rebuild_row(Size)),
    gate_cost.

%   gate_cost: what the rebuild's gate (oro_store_read/1) costs a call,
%   in process, against once/1.

gate_cost :-
    N = 1000000,
    bench_time(forall(between(1, N, _), oro_store_read(true)), Gate),
    bench_time(forall(between(1, N, _), once(true)), Bare),
    PerCall is (Gate - Bare) / N,
    format("~noro_store_read/1: ~3f us a call (~D calls)~n", [PerCall, N]).

%   churn(+Conn, +Pid, +Names): Names fresh names, 1000 per add/remove
%   pair, a row every million.

churn(Conn, Pid, Names) :-
    get_time(T0),
    row(Pid, 0, T0),
    Batches is Names // 1000,
    forall(between(1, Batches, B),
           ( batch(B, Set),
             bench_call(Conn, add, [Set], _, 60),
             bench_call(Conn, remove, [Set], _, 60),
             (   B mod 1000 =:= 0
             ->  N is B * 1000,
                 row(Pid, N, T0)
             ;   true
             )
           )).

batch(B, Set) :-
    with_output_to(string(Set),
                   ( write('['),
                     forall(between(1, 500, K),
                            ( (   K > 1
                              ->  write(', ')
                              ;   true
                              ),
                              format("n~d_~d p o~d_~d", [B, K, B, K])
                            )),
                     write(']')
                   )).

row(Pid, N, T0) :-
    bench_memory(Pid, Memory),
    get_time(T),
    Seconds is T - T0,
    format("| ~D | ~D kB | ~1f |~n", [N, Memory.rss_kb, Seconds]),
    flush_output.

%   rebuild_row(+Triples): the time of oro_store_rebuild/0 with Triples
%   asserted triples, in memory and with a database directory.

rebuild_row(Size) :-
    rebuild_time([], Size, Memory),
    tmp_file(oro_bench_names, Dir),
    call_cleanup(rebuild_time([db(Dir)], Size, Db),
                 ( oro_close,
                   delete_directory_and_contents(Dir) )),
    format("| ~D | ~3f s | ~3f s |~n", [Size, Memory, Db]),
    flush_output.

rebuild_time(Options, Size, Seconds) :-
    oro_init(Options),
    bench_world(Size, World),
    bench_batches(World, 1000, Batches),
    forall(member(Batch, Batches), oro_add(myself, Batch)),
    get_time(T0),
    oro_store_rebuild,
    get_time(T1),
    Seconds is T1 - T0.
