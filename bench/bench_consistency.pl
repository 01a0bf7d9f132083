/*  oro benchmark: consistency checks, in-process and over the socket,
    at about 10k and 100k asserted triples over the common-sense
    ontology (the world of bench_common:bench_world/2).

        swipl bench/bench_consistency.pl [--sizes=10000,100000] [--samples=100]

    Rows:

      - full check: the whole model checked, as checkConsistency does
        when it knows nothing (oro_conflict/2 finding no conflict);
      - checkConsistency after an add: each sample follows a plain add
        of one statement, so the remembered verdict is one change
        old: the triple the add logged is checked incrementally (the
        first verdict, a full check, is made before the samples);
      - checkConsistency after a remove: each sample follows a plain
        remove of one statement (nothing to check);
      - checkConsistency unchanged: the verdict remembered for the
        current generation;
      - safeAdd of one statement, accepted: after a safeAdd the model is
        known consistent, so the check is incremental;
      - safeAdd of one statement, rejected (`stateI rdf:type Event` on
        a StaticSituation, a disjoint class), also incremental;
      - safeAdd of one statement after a plain add: the added triple,
        then the statement, checked incrementally;
      - checkConsistency(Set) of one statement: incremental.

    The socket rows run the real server (server/oro_server.pl) as a
    child process.
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
    option(samples(Samples), Options, 100),
    bench_machine,
    nl,
    bench_header(triples),
    forall(member(Size, Sizes),
           ( in_process(Size, Samples),
             socket(Size, Samples)
           )).

		 /*******************************
		 *          IN PROCESS          *
		 *******************************/

in_process(Size, Samples) :-
    oro_init([]),
    bench_world(Size, Texts),
    bench_batches(Texts, 1000, Batches),
    forall(member(B, Batches), oro_add(myself, B)),
    FullSamples is max(5, Samples // 5),
    bench_measure(FullSamples, _, \+ oro_conflict(myself, _), true, Full),
    report('proc full check', Size, Full),
    oro_consistent(myself),                 % the first verdict: a full check
    bench_measure(Samples, I, oro_consistent(myself),
                  ( format(string(S), "mark~d isOn furniture1", [I]),
                    oro_add(myself, [S])
                  ),
                  AfterAdd),
    report('proc checkConsistency (+add)', Size, AfterAdd),
    bench_measure(Samples, I, oro_consistent(myself),
                  ( format(string(S), "mark~d isOn furniture1", [I]),
                    oro_remove(myself, [S])
                  ),
                  AfterRemove),
    report('proc checkConsistency (+remove)', Size, AfterRemove),
    bench_measure(Samples, _, oro_consistent(myself), true, Cached),
    report('proc checkConsistency (unchanged)', Size, Cached),
    bench_measure(Samples, I, oro_safe_add(myself, [S], longterm, true),
                  format(string(S), "new~d isOn furniture2", [I]),
                  Accepted),
    report('proc safeAdd 1 (accepted)', Size, Accepted),
    bench_measure(Samples, I, oro_safe_add(myself, [S], longterm, false),
                  ( format(string(R), "state~d rdf:type StaticSituation", [I]),
                    oro_safe_add(myself, [R], longterm, true),
                    format(string(S), "state~d rdf:type Event", [I])
                  ),
                  Rejected),
    report('proc safeAdd 1 (rejected)', Size, Rejected),
    bench_measure(Samples, I, oro_safe_add(myself, [S], longterm, true),
                  ( format(string(A), "plain~d isOn furniture3", [I]),
                    oro_add(myself, [A]),
                    format(string(S), "after~d isOn furniture3", [I])
                  ),
                  SafeAfterAdd),
    report('proc safeAdd 1 (after an add)', Size, SafeAfterAdd),
    bench_measure(Samples, I, oro_consistent_with(myself, [S]),
                  format(string(S), "maybe~d isOn furniture4", [I]),
                  With),
    report('proc checkConsistency(1 stmt)', Size, With).

report(Name, Size, Times) :-
    bench_report(Name, Size, Times, [units(auto)]).

		 /*******************************
		 *          OVER SOCKET         *
		 *******************************/

socket(Size, Samples) :-
    bench_with_server([], Port, _,
                      bench_with_connection(Port, C,
                                            socket_figures(C, Size, Samples))).

socket_figures(C, Size, Samples) :-
    bench_world(Size, Texts),
    bench_batches(Texts, 1000, Batches),
    forall(member(B, Batches), bench_call(C, add, [B])),
    bench_call(C, checkConsistency, [], "true"),   % the first: a full check
    bench_measure(Samples, I, bench_call(C, checkConsistency, [], "true"),
                  ( format(string(S), "mark~d isOn furniture1", [I]),
                    bench_call(C, add, [[S]])
                  ),
                  AfterAdd),
    report('socket checkConsistency (+add)', Size, AfterAdd),
    bench_measure(Samples, _, bench_call(C, checkConsistency, [], "true"), true,
                  Cached),
    report('socket checkConsistency (same)', Size, Cached),
    bench_measure(Samples, I, bench_call(C, safeAdd, [[S]], "true"),
                  format(string(S), "new~d isOn furniture2", [I]),
                  Accepted),
    report('socket safeAdd 1 (accepted)', Size, Accepted),
    bench_measure(Samples, I, bench_call(C, safeAdd, [[S]], "false"),
                  ( format(string(R), "state~d rdf:type StaticSituation", [I]),
                    bench_call(C, safeAdd, [[R]], "true"),
                    format(string(S), "state~d rdf:type Event", [I])
                  ),
                  Rejected),
    report('socket safeAdd 1 (rejected)', Size, Rejected),
    bench_measure(Samples, I, bench_call(C, safeAdd, [[S]], "true"),
                  ( format(string(A), "plain~d isOn furniture3", [I]),
                    bench_call(C, add, [[A]]),
                    format(string(S), "after~d isOn furniture3", [I])
                  ),
                  SafeAfterAdd),
    report('socket safeAdd 1 (after an add)', Size, SafeAfterAdd),
    bench_measure(Samples, I, bench_call(C, checkConsistency, [[S]], "true"),
                  format(string(S), "maybe~d isOn furniture4", [I]),
                  With),
    report('socket checkConsistency(1 stmt)', Size, With).
