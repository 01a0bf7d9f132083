/*  oro benchmark: concept comparison (discriminate, getSimilarities,
    getDifferences) over 10, 100 and 1,000 candidate individuals with 5
    to 20 properties each, over the common-sense ontology.

        swipl bench/bench_categorization.pl [--sizes=10,100,1000] [--runs=15]

    Every candidate has a class (Cup, Book, Box, ...) and 5 to 20
    properties drawn from the common-sense ones (hasColor, hasShape,
    hasSize, isOn, isNextTo, isVisible, ...) and from plain ones
    (p1..p12), with values from small pools so that candidates share
    values; the world comes from a fixed seed.  The figures are medians
    (and 90th percentiles) of the wall-clock time of one call, in
    process (the Prolog API) and over the socket (a server started in
    this process, on a free port).  It prints one table.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro)).
:- use_module(library(oro/questions/oro_categorize)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(random)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).
:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../server/oro_server', Server),
   use_module(Server),
   atom_concat(Dir, '/../test/oro_test_client', Client),
   use_module(Client).

:- initialization(main, main).

opt_type(sizes, sizes, term).
opt_type(runs, runs, natural).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    bench_list_option(sizes(Sizes), Options, [10, 100, 1000]),
    option(runs(Runs), Options, 15),
    bench_machine,
    oro_server_start([port(0), host('127.0.0.1')], Server),
    oro_server_port(Server, Port),
    format("~n~w~t~30|~w~t~12+~w~t~12+~w~t~12+~w~t~12+~w~n",
           [operation, candidates, triples, 'best', median, p90]),
    forall(member(N, Sizes),
           bench_size(Port, N, Runs)),
    oro_server_stop(Server).

		 /*******************************
		 *          THE WORLD           *
		 *******************************/

%   world(+N, -Names, -Statements): N candidates, seeded.

world(N, Names, Statements) :-
    set_random(seed(N)),
    findall(Name, ( between(1, N, I), format(atom(Name), 'cand~d', [I]) ),
            Names),
    foldl(candidate, Names, Statements, []).

candidate(Name, S0, S) :-
    random_member(Class, ['Cup', 'Book', 'Box', 'Toy', 'Bottle', 'Glass',
                          'VideoTape']),
    format(string(T), "~w rdf:type ~w", [Name, Class]),
    random_between(5, 20, K),
    properties(Ps),
    random_permutation(Ps, Shuffled),
    length(Chosen, K),
    append(Chosen, _, Shuffled),
    maplist(fact(Name), Chosen, Facts),
    S0 = [T|S1],
    append(Facts, S, S1).

properties([ hasColor, hasShape, hasSize, isOn, isNextTo, isVisible,
             isReachable, isMoving, hasCharacteristicWeight, belongsTo,
             p1, p2, p3, p4, p5, p6, p7, p8, p9, p10, p11, p12 ]).

fact(Name, P, S) :-
    value(P, V),
    format(string(S), "~w ~w ~w", [Name, P, V]).

value(hasColor, V) :- !, random_member(V, [red, green, blue, yellow, black, white]).
value(hasShape, V) :- !, random_member(V, [boxShape, cylinderShape, sphereShape]).
value(hasSize, V)  :- !, random_member(V, [small, medium, large]).
value(isOn, V)     :- !, random_between(1, 20, I), format(atom(V), 'table~d', [I]).
value(isNextTo, V) :- !, random_between(1, 50, I), format(atom(V), 'thing~d', [I]).
value(belongsTo, V) :- !, random_member(V, [alice, bob, myself]).
value(hasCharacteristicWeight, V) :- !, random_between(1, 500, V).
value(P, V) :-
    memberchk(P, [isVisible, isReachable, isMoving]),
    !,
    random_member(V, [true, false]).
value(_, V) :-
    random_between(1, 30, I),
    format(atom(V), 'v~d', [I]).

		 /*******************************
		 *           MEASURES           *
		 *******************************/

bench_size(Port, N, Runs) :-
    oro_reset,
    world(N, Names, Statements),
    oro_add(myself, Statements),
    rdf_statistics(triples(Triples)),
    oro_discriminate(myself, Names, _, Best),        % warm the schema
    length(Best, NBest),
    row('oro_discriminate/4', N, Triples, NBest, Runs,
        oro_discriminate(myself, Names, _, _)),
    row('oro_discriminants/3', N, Triples, NBest, Runs,
        oro_discriminants(myself, Names, _)),
    atomic_list_concat(Names, ', ', Joined),
    format(string(Set), "[~w]", [Joined]),
    setup_call_cleanup(
        oro_connect(Port, Conn),
        row('discriminate (socket)', N, Triples, NBest, Runs,
            ok_call(Conn, discriminate, [Set])),
        oro_disconnect(Conn)),
    Names = [A, B|_],
    row('oro_similarities/4', N, Triples, -, Runs,
        oro_similarities(myself, A, B, _)),
    row('oro_differences/4', N, Triples, -, Runs,
        oro_differences(myself, A, B, _)).

ok_call(Conn, Method, Params) :-
    oro_call(Conn, Method, Params, Reply),
    Reply = ok(_).

:- meta_predicate
    row(+, +, +, +, +, 0),
    time_once(0, -).

row(Name, N, Triples, NBest, Runs, Goal) :-
    findall(T, ( between(1, Runs, _), time_once(Goal, T) ), Ts),
    msort(Ts, Sorted),
    percentile(Sorted, 50, Median),
    percentile(Sorted, 90, P90),
    format("~w~t~30|~d~t~12+~d~t~12+~w~t~12+~3f ms~t~12+~3f ms~n",
           [Name, N, Triples, NBest, Median/1000, P90/1000]).

%   time_once(:Goal, -Micros): bench_time/2, but Goal must succeed.

time_once(Goal, Micros) :-
    (   bench_time(Goal, Micros)
    ->  true
    ;   throw(bench_failed(Goal))
    ).

%   percentile(+Sorted, +P, -X): nearest rank.

percentile(Sorted, P, X) :-
    length(Sorted, Len),
    I is max(0, min(Len - 1, ceiling(Len * P / 100) - 1)),
    nth0(I, Sorted, X).
