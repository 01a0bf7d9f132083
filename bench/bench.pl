/*  oro benchmark: latency of add, check and find, in-process and over
    the socket, at about 10k and 100k asserted triples, and bulk-add
    throughput.

        swipl bench/bench.pl [--sizes=10000,100000] [--samples=300]

    It starts the real server (server/oro_server.pl --port=0) as a
    child process for the socket figures, and prints one table.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(option)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(sizes, sizes, term).
opt_type(samples, samples, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    bench_list_option(sizes(Sizes), Options, [10000, 100000]),
    option(samples(Samples), Options, 300),
    bench_machine,
    nl,
    bench_header(triples),
    forall(member(Size, Sizes),
           ( bench_in_process(Size, Samples),
             bench_socket(Size, Samples)
           )).

		 /*******************************
		 *          IN PROCESS          *
		 *******************************/

bench_in_process(Size, Samples) :-
    oro_init([]),
    bench_world(Size, Texts),
    bench_batches(Texts, 100, Batches),
    length(Texts, NStmts),
    get_time(T0),
    forall(member(B, Batches), oro_add(myself, B)),
    get_time(T1),
    Rate is NStmts / max(0.000001, T1-T0),
    bench_row('in-process bulk add (batches of 100)', Size, -, -, Rate),
    Objects is Size // 4,
    bench_measure(Samples, I, oro_add(myself, [Stmt]),
                  format(string(Stmt), "extra~d isOn furniture1", [I]),
                  Add),
    bench_report('in-process add 1', Size, Add),
    bench_measure(Samples, I, oro_check(myself, [Stmt]),
                  ( J is 1 + I mod Objects,
                    F is J mod 50,
                    format(string(Stmt), "obj~d isOn furniture~d", [J, F])
                  ),
                  Check),
    bench_report('in-process check (asserted)', Size, Check),
    bench_measure(Samples, I, oro_check(myself, [Stmt]),
                  ( J is 1 + I mod Objects,
                    format(string(Stmt), "obj~d rdf:type Artifact", [J])
                  ),
                  CheckInf),
    bench_report('in-process check (inferred type)', Size, CheckInf),
    bench_measure(Samples, I, oro_find(myself, o, [P], _),
                  ( F is I mod 50,
                    format(string(P), "?o isAt furniture~d", [F])
                  ),
                  Find1),
    bench_report('in-process find (1 pattern)', Size, Find1),
    bench_measure(Samples, I, oro_find(myself, o, [P1, P2], _),
                  ( F is I mod 50,
                    format(string(P1), "?o isAt furniture~d", [F]),
                    P2 = "?o rdf:type Tableware"
                  ),
                  Find2),
    bench_report('in-process find (2 patterns)', Size, Find2).

		 /*******************************
		 *          OVER SOCKET         *
		 *******************************/

%   The real server as a child process (bench_with_server/4), one
%   connection.

bench_socket(Size, Samples) :-
    bench_with_server([], Port, _,
                      bench_with_connection(Port, C,
                                            socket_figures(C, Size, Samples))).

socket_figures(C, Size, Samples) :-
    bench_world(Size, Texts),
    bench_batches(Texts, 100, Batches),
    length(Texts, NStmts),
    get_time(T0),
    forall(member(B, Batches), bench_call(C, add, [B])),
    get_time(T1),
    Rate is NStmts / max(0.000001, T1-T0),
    bench_row('socket bulk add (batches of 100)', Size, -, -, Rate),
    Objects is Size // 4,
    bench_measure(Samples, I, bench_call(C, add, [[S]]),
                  format(string(S), "extra~d isOn furniture1", [I]),
                  Add),
    bench_report('socket add 1', Size, Add),
    bench_measure(Samples, I, bench_call(C, check, [[S]]),
                  ( J is 1 + I mod Objects,
                    F is J mod 50,
                    format(string(S), "obj~d isOn furniture~d", [J, F])
                  ),
                  Check),
    bench_report('socket check (asserted)', Size, Check),
    bench_measure(Samples, I, bench_call(C, check, [[S]]),
                  ( J is 1 + I mod Objects,
                    format(string(S), "obj~d rdf:type Artifact", [J])
                  ),
                  CheckInf),
    bench_report('socket check (inferred type)', Size, CheckInf),
    bench_measure(Samples, I, bench_call(C, find, ["o", [P]]),
                  ( F is I mod 50,
                    format(string(P), "?o isAt furniture~d", [F])
                  ),
                  Find1),
    bench_report('socket find (1 pattern)', Size, Find1),
    bench_measure(Samples, I, bench_call(C, find, ["o", [P1, P2]]),
                  ( F is I mod 50,
                    format(string(P1), "?o isAt furniture~d", [F]),
                    P2 = "?o rdf:type Tableware"
                  ),
                  Find2),
    bench_report('socket find (2 patterns)', Size, Find2).
