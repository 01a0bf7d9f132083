/*  oro SPARQL benchmark: joins of 3 to 5 patterns and a filter-heavy
    find at about 100k asserted triples, in process and over the
    socket (query, find with filters, sparql), plus parsing alone.

        swipl bench/bench_sparql.pl [--size=100000] [--samples=200]

    The world is bench_common's synthetic robot world (objects typed under
    common-sense classes, placed on 50 pieces of furniture, coloured and
    visible: 4 triples an object) over the common-sense ontology.  The
    socket figures use a server started in this process on a free port.
    Prints one table; times are wall-clock medians and 99th percentiles.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(oro)).
:- use_module(library(oro/sparql/oro_sparql)).
:- use_module(library(oro/oro_store), [oro_asserted_count/2]).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).
:- use_module(oro_bench('../server/oro_server')).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(size, size, nonneg).
opt_type(samples, samples, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(size(Size), Options, 100000),
    option(samples(Samples), Options, 200),
    bench_machine,
    format("~n~w~t~52|~w~t~10+~w~t~12+~w~t~12+~w~t~10+ ~w~n",
           [operation, triples, median, p99, 'per second', rows]),
    oro_init([]),
    load_world(Size, Asserted),
    bench_in_process(Asserted, Samples),
    bench_socket(Size, Samples).

		 /*******************************
		 *           THE WORLD          *
		 *******************************/

%   load_world(+Size, -Asserted): add bench_world/2's world of about
%   Size triples in batches of 1000; Asserted triples in the model.

load_world(Size, Asserted) :-
    bench_world(Size, Statements),
    bench_batches(Statements, 1000, Batches),
    forall(member(B, Batches), oro_add(myself, B)),
    oro_asserted_count(myself, Asserted).

		 /*******************************
		 *           QUERIES            *
		 *******************************/

%   query(?Name, +I, -Text): the I-th sample of a query; the furniture
%   varies with I (always an even one, so that every join has rows).

query('join 3 (isOn, type, colour)', I, Q) :-
    furniture(I, F),
    format(string(Q),
           "SELECT ?o WHERE { ?o oro:isOn oro:furniture~d . \c
            ?o rdf:type oro:Cup . ?o oro:hasColor oro:red }", [F]).
query('join 4 (+ visible)', I, Q) :-
    furniture(I, F),
    format(string(Q),
           "SELECT ?o WHERE { ?o oro:isOn oro:furniture~d ; rdf:type oro:Cup ; \c
            oro:hasColor oro:red ; oro:isVisible true }", [F]).
query('join 5 (inferred type, isAt, ?c)', I, Q) :-
    furniture(I, F),
    format(string(Q),
           "SELECT ?o ?c WHERE { ?o oro:isAt oro:furniture~d ; \c
            rdf:type oro:Tableware ; oro:hasColor ?c ; oro:isVisible true ; \c
            oro:isOn ?where }", [F]).
query('join 4, selective pattern last', I, Q) :-
    furniture(I, F),
    format(string(Q),
           "SELECT ?o WHERE { ?o oro:isVisible true . ?o oro:hasColor oro:red . \c
            ?o rdf:type oro:Cup . ?o oro:isOn oro:furniture~d }", [F]).
query('group by colour, count', I, Q) :-
    furniture(I, F),
    format(string(Q),
           "SELECT ?c (COUNT(?o) AS ?n) WHERE { ?o oro:isOn oro:furniture~d ; \c
            oro:hasColor ?c } GROUP BY ?c ORDER BY DESC(?n)", [F]).

furniture(I, F) :-
    F is (2 * I) mod 50.

%   The filter-heavy find: three patterns and four filters.

find_args(I, o, Patterns, Filters) :-
    furniture(I, F),
    format(string(P1), "?o isOn furniture~d", [F]),
    Patterns = [P1, "?o hasColor ?c", "?o isVisible ?v", "?o rdf:type ?t"],
    Filters = [ "?c != oro:red && ?c != oro:blue",
                "?v = true",
                "regex(str(?o), '[02468]$')",
                "?t IN (oro:Cup, oro:Book, oro:Toy) || STRSTARTS(STR(?t), STR(oro:Bo))"
              ].

		 /*******************************
		 *          IN PROCESS          *
		 *******************************/

bench_in_process(Size, Samples) :-
    forall(query(Name, 1, _),
           ( measure(Samples, I, oro_sparql(myself, Q, select(_, Rows)),
                     query(Name, I, Q), Rows, Times, NRows),
             atom_concat('sparql: ', Name, Label),
             report(Label, Size, Times, NRows)
           )),
    measure(Samples, I, oro_find(myself, V, Ps, Fs, Vs),
            find_args(I, V, Ps, Fs), Vs, FindTimes, FindRows),
    report('find, 4 patterns + 4 filters', Size, FindTimes, FindRows),
    measure(Samples, I, oro_find(myself, V, Ps, Vs),
            find_args(I, V, Ps, _), Vs, Find0Times, Find0Rows),
    report('find, the same 4 patterns alone', Size, Find0Times, Find0Rows),
    measure(Samples, I, oro_sparql_parse(Q, _),
            query('join 5 (inferred type, isAt, ?c)', I, Q), [], ParseTimes, _),
    report('parse a 5-pattern query', Size, ParseTimes, 0),
    measure(Samples, I, oro_sparql_json(myself, Q, _),
            query('join 4 (+ visible)', I, Q), [], JSONTimes, _),
    report('sparql JSON, join 4', Size, JSONTimes, 0).

		 /*******************************
		 *          OVER SOCKET         *
		 *******************************/

bench_socket(Size, Samples) :-
    setup_call_cleanup(
        oro_server_start([port(0), host('127.0.0.1')], Server),
        ( load_world(Size, Asserted),
          oro_server_port(Server, Port),
          bench_with_connection(Port, C,
                                socket_figures(C, Asserted, Samples))
        ),
        oro_server_stop(Server)).

%   Sets of patterns and filters are sent quoted (bench_send/3), as
%   liboro does, so that commas inside filters are kept.

socket_figures(C, Size, Samples) :-
    measure(Samples, I, bench_call(C, query, [o, Q]),
            query('join 4 (+ visible)', I, Q), [], QTimes, _),
    report('socket query, join 4', Size, QTimes, -),
    measure(Samples, I, bench_call(C, find, [V, quoted(Ps), quoted(Fs)]),
            find_args(I, V, Ps, Fs), [], FTimes, _),
    report('socket find, 4 patterns + 4 filters', Size, FTimes, -),
    measure(Samples, I, bench_call(C, sparql, [Q]),
            query('join 5 (inferred type, isAt, ?c)', I, Q), [], STimes, _),
    report('socket sparql (JSON), join 5', Size, STimes, -).

		 /*******************************
		 *          MEASURING           *
		 *******************************/

%   measure(+N, ?I, :Goal, :Prepare, ?Rows, -Times, -RowCount): run
%   Prepare then Goal for I in 1..N; Times are the Goal's wall times in
%   µs, RowCount the number of Rows of the last run.

:- meta_predicate measure(+, ?, 0, 0, ?, -, -).

measure(N, I, Goal, Prepare, Rows, Times, Count) :-
    findall(T-C, ( between(1, N, I),
                   once(Prepare),
                   bench_time(Goal, T),
                   (   is_list(Rows)
                   ->  length(Rows, C)
                   ;   C = 0
                   )
                 ), Pairs),
    pairs_keys_values(Pairs, Times, Counts),
    last(Counts, Count).

report(Name, Size, Times, Rows) :-
    bench_summary(Times, Median, P99),
    PerSecond is 1.0e6 / Median,
    bench_micros(Median, MText),
    bench_micros(P99, PText),
    format("~w~t~52|~d~t~10+~w~t~12+~w~t~12+~0f~t~10+ ~w~n",
           [Name, Size, MText, PText, PerSecond, Rows]),
    flush_output.
