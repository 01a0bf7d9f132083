/*  The reasoner and the store, in process, IRIs given (no parsing):
    the figures quoted in the module docs of oro_reason and oro_store.

        swipl bench/bench_reasoner.pl
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(oro/oro_store)).
:- use_module(library(semweb/rdf_db)).
:- use_module(bench_common).

:- initialization(main, main).

main :-
    bench_machine,
    bench_header(triples),
    assert_rate(false),                 % before oro: no watcher, no snapshot
    assert_rate(true),
    oro_init([]),
    rdf_equal(oro:isOn, IsOn),
    rdf_equal(rdf:type, Type),
    rdf_equal(oro:'Cup', Cup),
    forall(between(1, 25000, I),
           ( obj(I, O), J is I mod 50, furniture(J, F),
             oro_store_write(bench,
                             oro_store_assert(myself,
                                              [rdf(O, IsOn, F), rdf(O, Type, Cup)],
                                              longterm))
           )),
    obj(77, O), furniture(27, F),
    N = 20000,
    probe('rdf/3 probe', rdf(O, IsOn, F), N),
    probe('asserted in the model', oro_asserted(myself, O, IsOn, F), N),
    probe('holds x isOn y', oro_holds(myself, O, IsOn, F), N),
    probe('holds x isAt y (via isOn)', oro_holds(myself, O, oro:isAt, F), N),
    probe('asserted type', oro_holds(myself, O, Type, Cup), N),
    probe('inferred type (Cup < Artifact)', oro_holds(myself, O, Type, oro:'Artifact'), N),
    probe('false type', \+ oro_holds(myself, O, Type, oro:'Human'), N),
    bench_measure(20, I, oro_holds(myself, myself, Type, _),
                  ( format(atom(C), 'BenchClass~d', [I]),
                    oro_add(myself, [rdf(C, rdfs:subClassOf, oro:'Artifact')])
                  ), Compile),
    bench_report('schema recompile (common sense)', 50000, Compile).

probe(Name, Goal, N) :-
    bench_measure(N, _, Goal, true, Times),
    bench_report(Name, 50000, Times).

obj(I, O) :-
    format(atom(O), 'http://kb.openrobots.org#obj~d', [I]).
furniture(J, F) :-
    format(atom(F), 'http://kb.openrobots.org#furniture~d', [J]).

%   rdf_assert/4 on an empty store, with default and presized hashes.

assert_rate(Presize) :-
    rdf_reset_db,
    (   Presize == true
    ->  forall(member(I, [s, p, o, sp, po, spo, g, sg, pg]),
               rdf_set(hash(I, size, 262144)))
    ;   true
    ),
    numlist(1, 100000, L),
    findall(O, (member(I, L), obj(I, O)), Os),
    get_time(T0),
    forall(member(O, Os), rdf_assert(O, oro:isOn, oro:table, g)),
    get_time(T1),
    Us is (T1 - T0) / 100000 * 1.0e6,
    format(atom(Name), 'rdf_assert, presized=~w', [Presize]),
    bench_row(Name, 100000, Us, -, 1.0e6 / Us).
