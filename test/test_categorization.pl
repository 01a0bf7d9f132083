:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).
:- use_module(library(oro/questions/oro_categorize)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(random)).

/*  Tests of concept comparison (ORO-SPEC §6.5, §10, vectors of §13.9):
    getSimilarities, getDifferences, discriminate and
    discriminateForAgent.

      - the Prolog API of oro_categorize over the test ontology
        (test/fixtures/testsuite.ttl): the vectors of §10 and §13.9,
        the seed's "give me the thing" example, errors, determinism;
      - property-based tests on seeded random worlds: what
        discriminate returns separates the individuals as it claims,
        and no property separates them better; similarities hold for
        both individuals, differences for one only;
      - every vector of §13.9 and §10 over a real socket, error
        replies included, with the server started in-process on a free
        port;
      - the seed example on the OpenRobots ontology
        (../shared/ontologies/oro.owl, skipped with a notice if absent)
        and on oro's own common-sense ontology.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_categorization.pl
*/

%   The OpenRobots ontology, if the shared reference files are there.

cat_openrobots(Path) :-
    test_checkout_path('../shared/ontologies/oro.owl', Path),
    exists_file(Path).

cat_openrobots_available :-
    (   cat_openrobots(_)
    ->  true
    ;   print_message(informational,
                      format('test_categorization: ../shared/ontologies/\c
                              oro.owl not found: OpenRobots ontology tests \c
                              skipped', [])),
        fail
    ).


                 /*******************************
                 *          FIXTURES            *
                 *******************************/

%   The test ontology alone, in-process.

cat_testsuite :-
    test_store_testsuite.

%   The setup of §13.9: sheepy and baboon2.

cat_setup_13_9 :-
    cat_testsuite,
    oro_add(myself, ["sheepy eats grass",
                     "baboon2 rdf:type Monkey",
                     "baboon2 age 75"]).

%   The seed's example: which thing does the human want?

cat_seed_statements(
    [ "plant1 rdf:type Plant", "plant1 hasColor green",
      "animal1 rdf:type Animal", "animal1 eats banana",
      "animal2 rdf:type Animal", "animal2 eats grass",
      "animal2 hasColor blue",
      "animal3 rdf:type Animal", "animal3 hasColor red"
    ]).

cat_seed :-
    cat_testsuite,
    cat_seed_statements(Statements),
    oro_add(myself, Statements).

%   cat_names(+IRIs, -Names): contracted, in order.

cat_names(IRIs, Names) :-
    maplist(oro_iri_name, IRIs, Names).

%   cat_similar_texts(+A, +B, -Texts): similarities in light form,
%   sorted.

cat_similar_texts(A, B, Texts) :-
    oro_similarities(myself, A, B, Sims),
    findall(T, ( member(similar(P, V), Sims),
                 oro_term_light_text(P, PT),
                 oro_term_light_text(V, VT),
                 atomic_list_concat([PT, VT], ' ', T)
               ), Texts0),
    msort(Texts0, Texts).

%   cat_difference_texts(+A, +B, -Groups): each group sorted, groups
%   sorted.

cat_difference_texts(A, B, Groups) :-
    oro_differences(myself, A, B, Diffs),
    maplist(cat_group_texts, Diffs, Groups0),
    msort(Groups0, Groups).

cat_group_texts(Triples, Texts) :-
    findall(T, ( member(rdf(S, P, O), Triples),
                 maplist(oro_term_light_text, [S, P, O], Parts),
                 atomic_list_concat(Parts, ' ', T)
               ), Texts0),
    msort(Texts0, Texts).

%   cat_short(+Term, -Short): the IRIs in Term written Prefix:Local, as
%   expectations are (rdf_meta does not expand test options).

cat_short(Term, Short) :-
    atom(Term),
    rdf_global_id(Prefix:Local, Term),
    !,
    Short = Prefix:Local.
cat_short(Term, Short) :-
    compound(Term),
    Term \= _:_,
    !,
    Term =.. [F|Args0],
    maplist(cat_short, Args0, Args),
    Short =.. [F|Args].
cat_short(Term, Term).

cat_discriminate(Names, Total, Best) :-
    oro_discriminate(myself, Names, TotalIRIs, BestIRIs),
    cat_names(TotalIRIs, Total),
    cat_names(BestIRIs, Best).


                 /*******************************
                 *         SIMILARITIES         *
                 *******************************/

:- begin_tests(categorization_similarities, [setup(cat_setup_13_9)]).

test(cow_sheepy, true(T == ['eats grass', 'rdf:type Animal'])) :-
    cat_similar_texts(cow, sheepy, T).
test(cow_gorilla, true(T == ['age 12', 'isFemale false', 'rdf:type Animal'])) :-
    cat_similar_texts(cow, gorilla, T).
test(baboon_baboon2, true(T == ['rdf:type Monkey'])) :-
    cat_similar_texts(baboon, baboon2, T).
test(lattice_f_j, true(T == ['rdf:type B', 'rdf:type D'])) :-
    cat_similar_texts(f, j, T).
test(lattice_f_k, true(T == ['rdf:type B', 'rdf:type D'])) :-
    cat_similar_texts(f, k, T).
test(lattice_f_e, true(T == ['rdf:type E'])) :-
    cat_similar_texts(f, e, T).
test(lattice_f_f, true(T == ['rdf:type F'])) :-
    cat_similar_texts(f, f, T).
test(terms, true(Sims == [ similar(rdf:type, oro:'Animal'),
                           similar(oro:age, literal(type(xsd:int, '12'))),
                           similar(oro:isFemale,
                                   literal(type(xsd:boolean, false)))
                         ])) :-
    oro_similarities(myself, oro:cow, oro:gorilla, Sims0),
    cat_short(Sims0, Sims).
test(prefixed_and_full_names, true(S1 == S2)) :-
    oro_similarities(myself, oro:cow, 'http://kb.openrobots.org#sheepy', S1),
    oro_similarities(myself, cow, sheepy, S2).
test(alias_default, true(S1 == S2)) :-
    oro_similarities(default, cow, sheepy, S1),
    oro_similarities(myself, cow, sheepy, S2).
test(common_ancestors, true(Cs == [oro:'B', oro:'D'])) :-
    oro_common_ancestors(myself, f, j, Cs0),
    cat_short(Cs0, Cs).
test(common_ancestors_same_class, true(Cs == [oro:'Monkey', oro:'MyAnimals'])) :-
    oro_common_ancestors(myself, baboon, gorilla, Cs0),
    cat_short(Cs0, Cs).
test(nothing_but_thing, [ setup(oro_add(myself, ["lonely rdf:type Plant"])),
                          true(T == ['rdf:type owl:Thing'])
                        ]) :-
    cat_similar_texts(cow, lonely, T).
test(literals_by_value,
     [ setup(oro_add(myself, ["calf age 12^^xsd:integer"])),
       true(T == ['age 12', 'rdf:type Animal'])
     ]) :-
    cat_similar_texts(cow, calf, T).

:- end_tests(categorization_similarities).


                 /*******************************
                 *          DIFFERENCES         *
                 *******************************/

:- begin_tests(categorization_differences, [setup(cat_setup_13_9)]).

test(cow_sheepy, true(G == [])) :-
    cat_difference_texts(cow, sheepy, G).
test(cow_gorilla,
     true(G == [ ['cow eats grass', 'gorilla eats apple'],
                 ['cow rdf:type Animal', 'gorilla rdf:type Monkey',
                  'gorilla rdf:type MyAnimals'],
                 ['cow weight 150.7', 'gorilla weight 100.2']
               ])) :-
    cat_difference_texts(cow, gorilla, G).
test(baboon_baboon2,
     [ setup(oro_add(myself, ["baboon2 rdf:type MyAnimals"])),
       cleanup(oro_remove(myself, ["baboon2 rdf:type MyAnimals"])),
       true(G == [['baboon age 35', 'baboon2 age 75']])
     ]) :-
    cat_difference_texts(baboon, baboon2, G).
test(lattice_f_j, true(G == [ ['f rdf:type C', 'j rdf:type J'],
                              ['f rdf:type E', 'j rdf:type I']
                            ])) :-
    cat_difference_texts(f, j, G).
test(lattice_f_k, true(G == [ ['f rdf:type C', 'k rdf:type K'],
                              ['f rdf:type E', 'k rdf:type K']
                            ])) :-
    cat_difference_texts(f, k, G).
test(lattice_f_e, true(G == [['e rdf:type E', 'f rdf:type F']])) :-
    cat_difference_texts(f, e, G).
test(lattice_f_f, true(G == [])) :-
    cat_difference_texts(f, f, G).
test(equivalent_ancestors_one_group,   % X and Y: one question, asked once
     [ setup(oro_add(myself, [ "X owl:equivalentClass Y",
                               "Z1 rdfs:subClassOf X", "Z2 rdfs:subClassOf X",
                               "a1 rdf:type Z1", "b1 rdf:type Z2" ])),
       cleanup(oro_clear(myself, ["X ?p ?o", "Z1 ?p ?o", "Z2 ?p ?o",
                                  "a1 ?p ?o", "b1 ?p ?o"])),
       true(G == [['a1 rdf:type Z1', 'b1 rdf:type Z2']])
     ]) :-
    oro_differences(myself, a1, b1, D),
    maplist(cat_group_texts, D, G).
test(terms_types_first,
     true(D == [ [ rdf(oro:cow, rdf:type, oro:'Animal'),
                   rdf(oro:gorilla, rdf:type, oro:'Monkey'),
                   rdf(oro:gorilla, rdf:type, oro:'MyAnimals')
                 ],
                 [ rdf(oro:cow, oro:eats, oro:grass),
                   rdf(oro:gorilla, oro:eats, oro:apple)
                 ],
                 [ rdf(oro:cow, oro:weight, literal(type(xsd:double, '150.7'))),
                   rdf(oro:gorilla, oro:weight, literal(type(xsd:double, '100.2')))
                 ]
               ])) :-
    oro_differences(myself, cow, gorilla, D0),
    cat_short(D0, D).

:- end_tests(categorization_differences).


                 /*******************************
                 *         DISCRIMINATE         *
                 *******************************/

:- begin_tests(categorization_discriminate).

cat_capucin :-
    cat_testsuite,
    oro_add(myself, ["capucin rdf:type Monkey", "capucin rdf:type MyAnimals"]).

test(capucin_gorilla, [ setup(cat_capucin),
                        true(T-B == []-[age, eats, isFemale, weight])
                      ]) :-
    cat_discriminate([capucin, gorilla], T, B).
test(capucin_eats, [ setup(( cat_capucin,
                             oro_add(myself, ["capucin eats grass"]) )),
                     true(T-B == [eats]-[eats])
                   ]) :-
    cat_discriminate([capucin, gorilla], T, B).
test(with_grass, [ setup(( cat_capucin,
                           oro_add(myself, ["capucin eats grass"]) )),
                   true(T-B == []-[eats, 'rdf:type'])
                 ]) :-
    cat_discriminate([capucin, gorilla, grass], T, B).
test(with_colours, [ setup(( cat_capucin,
                             oro_add(myself, [ "capucin eats grass",
                                               "capucin hasColor grey",
                                               "gorilla hasColor black",
                                               "grass hasColor green" ]) )),
                     true(T-B == [hasColor]-[hasColor])
                   ]) :-
    cat_discriminate([capucin, gorilla, grass], T, B).
test(climbs_on_pruned, [ setup(( cat_capucin,
                                 oro_add(myself, ["capucin climbsOn sunflower"]) )),
                         true(T-B == [climbsOn]-[climbsOn])
                       ]) :-
    cat_discriminate([capucin, baboon], T, B).
test(vervet_macaque, [ setup(( cat_testsuite,
                               oro_add(myself, [ "vervet climbsOn palmtree",
                                                 "macaque rdf:type Monkey",
                                                 "macaque isOn palmtree" ]) )),
                       true(T-B == []-[climbsOn])
                     ]) :-
    cat_discriminate([vervet, macaque], T, B).
test(vervet_macaque_coconut,
     [ setup(( cat_testsuite,
               oro_add(myself, [ "vervet climbsOn palmtree",
                                 "macaque rdf:type Monkey",
                                 "macaque isOn palmtree" ]),
               oro_remove(myself, ["macaque isOn palmtree"]),
               oro_add(myself, ["macaque climbsOn coconut"]) )),
       true(T-B == [climbsOn]-[climbsOn])
     ]) :-
    cat_discriminate([vervet, macaque], T, B).
test(seed_example, [ setup(cat_seed),
                     true(T-B == []-[hasColor])
                   ]) :-
    cat_discriminate([plant1, animal1, animal2, animal3], T, B).
test(seed_example_coloured, [ setup(cat_seed),
                              true(T-B == [hasColor]-[hasColor])
                            ]) :-
    cat_discriminate([plant1, animal2, animal3], T, B).
test(seed_example_animals, [ setup(cat_seed),
                             true(T-B == []-[eats, hasColor])
                           ]) :-
    cat_discriminate([animal1, animal2, animal3], T, B).
test(seed_discriminants,
     [ setup(cat_seed),
       true(Ds == [ discriminant(oro:hasColor,
                                 [ []-[oro:animal1],
                                   [oro:blue]-[oro:animal2],
                                   [oro:green]-[oro:plant1],
                                   [oro:red]-[oro:animal3]
                                 ])
                  ])
     ]) :-
    oro_discriminants(myself, [plant1, animal1, animal2, animal3], Ds0),
    cat_short(Ds0, Ds).
test(seed_type_partition,
     [ setup(cat_seed),
       true(P == [ [oro:'Animal']-[oro:animal1, oro:animal2, oro:animal3],
                   [oro:'Plant']-[oro:plant1]
                 ])
     ]) :-
    oro_partition(myself, [animal3, plant1, animal1, animal2], rdf:type, P0),
    cat_short(P0, P).
test(type_as_a_set, [ setup(cat_capucin),
                      true(Ds == [ discriminant(rdf:type,
                                                [ [oro:'Animal']-[oro:cow],
                                                  [oro:'Monkey', oro:'MyAnimals']
                                                  -[oro:capucin, oro:gorilla]
                                                ])
                                 ])
                    ]) :-
    oro_add(myself, ["capucin age 12", "capucin isFemale false",
                     "capucin weight 100.2", "capucin eats grass",
                     "gorilla eats grass", "gorilla isOn cow",
                     "capucin isOn cow"]),
    oro_discriminants(myself, [capucin, gorilla, cow], Ds0),
    include(cat_type_discriminant, Ds0, Ds1),
    cat_short(Ds1, Ds).

cat_type_discriminant(discriminant(P, _)) :-
    rdf_equal(P, rdf:type).
test(order_and_duplicates_ignored, [ setup(cat_seed),
                                     true(R1 == R2)
                                   ]) :-
    oro_discriminants(myself, [animal3, plant1, animal1, animal2, plant1], R1),
    oro_discriminants(myself, [plant1, animal1, animal2, animal3], R2).
test(empty_set, [ setup(cat_testsuite), true(T-B == []-[]) ]) :-
    oro_discriminate(myself, [], T, B).
test(identical_individuals, [ setup(( cat_testsuite,
                                      oro_add(myself, [ "twin1 rdf:type Monkey",
                                                        "twin1 eats apple",
                                                        "twin2 rdf:type Monkey",
                                                        "twin2 eats apple" ]) )),
                              true(T-B == []-[])
                            ]) :-
    oro_discriminate(myself, [twin1, twin2], T, B).
test(same_value_sets_do_not_separate,
     [ setup(( cat_testsuite,
               oro_add(myself, [ "m1 eats apple", "m1 eats grass",
                                 "m2 eats apple", "m2 eats grass",
                                 "m1 hasColor red", "m2 hasColor blue" ]) )),
       true(T-B == [hasColor]-[hasColor])
     ]) :-
    cat_discriminate([m1, m2], T, B).
test(value_sets_separate,
     [ setup(( cat_testsuite,
               oro_add(myself, [ "m1 eats apple", "m1 eats grass",
                                 "m2 eats apple", "m3 eats grass" ]) )),
       true(T-B == [eats]-[eats])
     ]) :-
    cat_discriminate([m1, m2, m3], T, B).
test(singleton, [ setup(cat_testsuite),
                  true(T-B == [age, climbsOn, isFemale, weight, 'rdf:type']-
                              [age, climbsOn, isFemale, weight, 'rdf:type'])
                ]) :-
    cat_discriminate([baboon], T, B).
test(agent_model, [ setup(( cat_testsuite,
                            oro_create_model(bob),
                            oro_add(bob, [ "x1 hasColor red",
                                           "x2 hasColor blue" ]),
                            oro_add(myself, [ "x1 hasSize small",
                                              "x2 hasSize large" ]) )),
                    true(Bob-Me == [hasColor]-[hasSize])
                  ]) :-
    oro_discriminate(bob, [x1, x2], Bob0, _),
    oro_discriminate(myself, [x1, x2], Me0, _),
    cat_names(Bob0, Bob),
    cat_names(Me0, Me).

:- end_tests(categorization_discriminate).


                 /*******************************
                 *            ERRORS            *
                 *******************************/

:- begin_tests(categorization_errors, [setup(cat_setup_13_9)]).

test(unknown_first,
     error(existence_error(concept, 'http://kb.openrobots.org#i_d_ont_exist'))) :-
    oro_similarities(myself, i_d_ont_exist, cow, _).
test(unknown_second,
     error(existence_error(concept, 'http://kb.openrobots.org#i_d_ont_exist'))) :-
    oro_differences(myself, cow, i_d_ont_exist, _).
test(instance_and_class,
     error(domain_error(oro_comparable, kinds(instance, class)))) :-
    oro_similarities(myself, baboon, 'Monkey', _).
test(class_and_instance,
     error(domain_error(oro_comparable, kinds(class, instance)))) :-
    oro_differences(myself, 'Monkey', baboon, _).
test(two_classes, error(domain_error(oro_comparable, not_individuals))) :-
    oro_similarities(myself, 'Monkey', 'Animal', _).
test(two_properties, error(domain_error(oro_comparable, not_individuals))) :-
    oro_differences(myself, eats, climbsOn, _).
test(discriminate_unknown,
     error(existence_error(concept, 'http://kb.openrobots.org#nobody_knows'))) :-
    oro_discriminate(myself, [cow, nobody_knows], _, _).
test(discriminate_class, error(domain_error(oro_comparable, not_individuals))) :-
    oro_discriminate(myself, [cow, 'Monkey'], _, _).
test(unknown_agent, error(existence_error(agent, nobody))) :-
    oro_discriminate(nobody, [cow, gorilla], _, _).
test(not_a_list, error(type_error(list, cow))) :-
    oro_discriminate(myself, cow, _, _).
test(unbound_individual, error(instantiation_error)) :-
    oro_similarities(myself, _, cow, _).

:- end_tests(categorization_errors).


                 /*******************************
                 *     PROPERTY-BASED TESTS     *
                 *******************************/

/*  Random worlds over the test ontology: 2 to 10 individuals typed in
    the A..K lattice or the zoo, with single-valued properties
    (hasColor, hasSize, age, isFemale, one of climbsOn ⊑ isOn ⊑ isAt)
    and, in "multi" worlds, multi-valued ones (likes, eats).  Every
    world comes from a fixed seed, so a failure names its seed.
*/

cat_world_seeds(single, Seeds) :-
    numlist(1, 40, Seeds).
cat_world_seeds(multi, Seeds) :-
    numlist(101, 140, Seeds).

%   cat_world(+Kind, +Seed, -Individuals): reset the robot's model and
%   fill it with a random world.

cat_world(Kind, Seed, Individuals) :-
    set_random(seed(Seed)),
    oro_reset,
    random_between(2, 10, N),
    findall(X, ( between(1, N, I), format(atom(X), 'gen~d', [I]) ), Individuals),
    foldl(cat_individual(Kind), Individuals, [], Statements),
    oro_add(myself, Statements).

cat_individual(Kind, X, S0, S) :-
    random_member(C, ['A', 'B', 'C', 'E', 'F', 'J', 'K', 'Monkey',
                      'MyAnimals', 'Plant']),
    format(string(T), "~w rdf:type ~w", [X, C]),
    findall(St, cat_fact(Kind, X, St), Facts),
    append([S0, [T], Facts], S).

cat_fact(_, X, S) :-
    cat_maybe(0.7),
    random_member(V, [red, green, blue]),
    format(string(S), "~w hasColor ~w", [X, V]).
cat_fact(_, X, S) :-
    cat_maybe(0.5),
    random_member(V, [small, large]),
    format(string(S), "~w hasSize ~w", [X, V]).
cat_fact(_, X, S) :-
    cat_maybe(0.5),
    random_between(1, 4, A),
    (   cat_maybe(0.5)
    ->  format(string(S), "~w age ~d", [X, A])
    ;   format(string(S), "~w age ~d^^xsd:integer", [X, A])
    ).
cat_fact(_, X, S) :-
    cat_maybe(0.4),
    random_member(B, [true, false]),
    format(string(S), "~w isFemale ~w", [X, B]).
cat_fact(_, X, S) :-
    cat_maybe(0.6),
    random_member(P, [climbsOn, isOn, isAt]),
    random_member(T, [tree1, tree2, rock]),
    format(string(S), "~w ~w ~w", [X, P, T]).
cat_fact(multi, X, S) :-
    cat_maybe(0.6),
    random_between(1, 3, N),
    findall(V, ( between(1, N, _), random_member(V, [v1, v2, v3]) ), Vs0),
    sort(Vs0, Vs),
    member(V, Vs),
    format(string(S), "~w likes ~w", [X, V]).
cat_fact(multi, X, S) :-
    cat_maybe(0.5),
    random_member(Vs, [[apple], [grass], [apple, grass]]),
    member(V, Vs),
    format(string(S), "~w eats ~w", [X, V]).

cat_maybe(P) :-
    random_float < P.

%   cat_specific(+X, +P, -Values): the values of P for X that no
%   sub-property of P carries as well (what discriminate compares), by
%   value, sorted; for rdf:type the direct classes.  Recomputed here
%   from oro_holds/4, independently of oro_categorize.

cat_specific(X, P, Values) :-
    rdf_equal(P, rdf:type),
    !,
    oro_direct_classes_of(myself, X, Values).
cat_specific(X, P, Values) :-
    findall(K, ( oro_holds(myself, X, P, O),
                 \+ ( oro_holds(myself, X, Q, O),
                      Q \== P,
                      oro_subproperty(myself, Q, P),
                      \+ oro_subproperty(myself, P, Q)
                    ),
                 cat_value_key(O, K)
               ), Ks),
    sort(Ks, Values).

%   cat_full(+X, +P, -Values): all values of P for X, by value.

cat_full(X, P, Values) :-
    rdf_equal(P, rdf:type),
    !,
    oro_direct_classes_of(myself, X, Values).
cat_full(X, P, Values) :-
    findall(K, ( oro_holds(myself, X, P, O), cat_value_key(O, K) ), Ks),
    sort(Ks, Values).

cat_value_key(literal(L), K) :-
    !,
    oro_literal_lexical(literal(L), Lex),
    (   atom_number(Lex, N)
    ->  K = N
    ;   K = Lex
    ).
cat_value_key(R, R).

%   cat_candidates(+Xs, -Ps): every property discriminate looks at.

cat_candidates(Xs, Ps) :-
    findall(P, ( member(X, Xs),
                 oro_holds(myself, X, P, _),
                 \+ cat_ignored(P)
               ), Ps0),
    rdf_equal(Type, rdf:type),
    sort([Type|Ps0], Ps).

cat_ignored(P) :-
    member(I, [rdf:type, owl:sameAs, owl:differentFrom, rdfs:label,
               rdfs:comment]),
    rdf_global_id(I, P),
    !.

%   cat_key(+Xs, +P, -Key): min(occ, number of distinct non-empty
%   specific value sets), 0 for a property that separates nothing.

cat_key(Xs, P, Key) :-
    findall(Vs, ( member(X, Xs),
                  cat_has(X, P),
                  cat_specific(X, P, Vs)
                ), Sets),
    length(Sets, Occ),
    sort(Sets, Distinct0),
    subtract(Distinct0, [[]], Distinct),
    length(Distinct, Count),
    (   ( Count =:= 0 ; Count =< 1, Occ > 1 )
    ->  Key = 0
    ;   Key is min(Occ, Count)
    ).

cat_has(X, P) :-
    rdf_equal(P, rdf:type),
    !,
    oro_individual(myself, X).
cat_has(X, P) :-
    oro_holds(myself, X, P, _),
    !.

%   cat_separates(+Xs, +P, :Values): two individuals differ.

cat_separates(Xs, P, Values) :-
    member(X, Xs),
    member(Y, Xs),
    X @< Y,
    call(Values, X, P, VX),
    call(Values, Y, P, VY),
    VX \== VY,
    !.

cat_all_apart(Xs, P, Values) :-
    forall(( member(X, Xs), member(Y, Xs), X @< Y ),
           ( call(Values, X, P, VX),
             call(Values, Y, P, VY),
             VX \== [],
             VY \== [],
             VX \== VY
           )).

%   cat_check_world(+Kind, +Seed): the properties of discriminate in
%   one world; fails with a message naming the seed.

cat_check_world(Kind, Seed) :-
    cat_world(Kind, Seed, Names),
    maplist(oro_name_iri, Names, Xs0),
    sort(Xs0, Xs),
    oro_discriminate(myself, Names, Total, Best),
    oro_discriminants(myself, Names, Ds),
    (   cat_world_ok(Kind, Xs, Total, Best, Ds)
    ->  true
    ;   format(user_error, "~nworld ~w ~w: total ~q best ~q~n",
               [Kind, Seed, Total, Best]),
        fail
    ).

cat_world_ok(Kind, Xs, Total, Best, Ds) :-
    % the claim is either nothing or everything
    ( Total == [] ; Total == Best ),
    % discriminants come in the same order as Best
    findall(P, member(discriminant(P, _), Ds), Best),
    % partitions: ordered blocks that cover the set exactly
    forall(member(discriminant(_, Partition), Ds),
           ( pairs_values(Partition, Blocks),
             forall(member(Block, Blocks), sort(Block, Block)),
             append(Blocks, Members),
             msort(Members, Xs)
           )),
    % every best discriminant separates the set
    forall(member(P, Best), cat_separates(Xs, P, cat_specific)),
    % a total one separates every pair
    forall(member(P, Total), cat_all_apart(Xs, P, cat_specific)),
    % no property does better (§10.5: the maximal key)
    cat_candidates(Xs, Candidates),
    foldl({Xs}/[P, M0, M]>>( cat_key(Xs, P, K), M is max(M0, K) ),
          Candidates, 0, MaxKey),
    (   Best == []
    ->  MaxKey =:= 0
    ;   forall(member(P, Best), cat_key(Xs, P, MaxKey))
    ),
    % with one value per property, the partitions (all values) agree
    (   Kind == single
    ->  forall(member(discriminant(_, Partition), Ds),
               Partition = [_, _|_]),
        (   Total == []
        ->  true
        ;   forall(member(discriminant(_, Partition), Ds),
                   forall(member(Vs-Ms, Partition),
                          ( Vs \== [], Ms = [_] )))
        )
    ;   true
    ).

%   cat_check_pair(+Seed): similarities hold for both individuals,
%   each difference for one of them only.

cat_check_pair(Seed) :-
    cat_world(multi, Seed, [A, B|_]),
    oro_name_iri(A, IA),
    oro_name_iri(B, IB),
    oro_similarities(myself, IA, IB, Sims),
    oro_differences(myself, IA, IB, Diffs),
    (   forall(member(similar(P, V), Sims),
               ( oro_holds(myself, IA, P, V),
                 oro_holds(myself, IB, P, V)
               )),
        forall(( member(Group, Diffs),
                 member(rdf(S, P, O), Group),
                 \+ rdf_equal(P, rdf:type)
               ),
               ( oro_holds(myself, S, P, O),
                 (   S == IA
                 ->  \+ oro_holds(myself, IB, P, O)
                 ;   \+ oro_holds(myself, IA, P, O)
                 )
               )),
        forall(( member(Group, Diffs),
                 member(rdf(S, P, C), Group),
                 rdf_equal(P, rdf:type)
               ),
               oro_type(myself, S, C))
    ->  true
    ;   format(user_error, "~npair world ~w: ~q ~q~n", [Seed, Sims, Diffs]),
        fail
    ).

:- begin_tests(categorization_properties, [setup(cat_testsuite)]).

test(single_valued_worlds, true(Failed == [])) :-
    cat_world_seeds(single, Seeds),
    exclude(cat_check_world(single), Seeds, Failed).
test(multi_valued_worlds, true(Failed == [])) :-
    cat_world_seeds(multi, Seeds),
    exclude(cat_check_world(multi), Seeds, Failed).
test(subsets_of_a_world, true(Failed == [])) :-
    cat_world(multi, 7, Names),
    findall(Sub, ( between(1, 30, I),
                   set_random(seed(I)),
                   include([_]>>cat_maybe(0.6), Names, Sub)
                 ), Subs),
    exclude(cat_check_subset, Subs, Failed).
test(similarities_and_differences_hold, true(Failed == [])) :-
    numlist(201, 230, Seeds),
    exclude(cat_check_pair, Seeds, Failed).

cat_check_subset(Names) :-
    maplist(oro_name_iri, Names, Xs0),
    sort(Xs0, Xs),
    oro_discriminate(myself, Names, Total, Best),
    oro_discriminants(myself, Names, Ds),
    cat_world_ok(multi, Xs, Total, Best, Ds).

:- end_tests(categorization_properties).


                 /*******************************
                 *        OVER THE SOCKET       *
                 *******************************/

%   The unit's server (test_server_start/1, test_server_stop/0).

cat_stop :-
    test_server_stop.

cat_start_testsuite :-
    test_server_start_testsuite.

%   cat_session(+Setup, +Method, +Params, -Reply): reset, run the
%   Setup requests (each must succeed), then the request.

cat_session(Setup, Method, Params, Reply) :-
    append([[reset-[]], Setup, [Method-Params]], Requests),
    test_calls(Requests, Replies),
    once(append(SetupReplies, [Reply], Replies)),
    forall(member(R, SetupReplies), R = ok(_)).

%   cat_sorted(+Reply, -Value): an ok reply's JSON value with every
%   list sorted (the spec compares them unordered).

cat_sorted(ok(Line), Value) :-
    !,
    test_json(Line, JSON),
    test_unordered(JSON, Value).
cat_sorted(Reply, Reply).

%   cat_discriminate_value(+Reply, -Value): [Total, Best], each sorted.

cat_discriminate_value(ok(Line), [Total, Best]) :-
    !,
    test_json(Line, [Total0, Best0]),
    msort(Total0, Total),
    msort(Best0, Best).
cat_discriminate_value(Reply, Reply).

cat_add_13_9("[sheepy eats grass, baboon2 rdf:type Monkey, baboon2 age 75]").

cat_similar(A, B, Value) :-
    cat_add_13_9(Add),
    cat_session([add-[Add]], getSimilarities, [A, B], Reply),
    cat_sorted(Reply, Value).

cat_differ(A, B, Value) :-
    cat_add_13_9(Add),
    cat_session([add-[Add]], getDifferences, [A, B], Reply),
    cat_sorted(Reply, Value).

cat_discriminate_after(Adds, Set, Value) :-
    findall(add-[A], member(A, Adds), Setup),
    cat_session(Setup, discriminate, [Set], Reply),
    cat_discriminate_value(Reply, Value).

:- begin_tests(categorization_protocol,
               [ setup(cat_start_testsuite),
                 cleanup(cat_stop)
               ]).

test(listed, true(Missing == [])) :-
    test_calls([listSimpleMethods-[]], [ok(Line)]),
    test_json(Line, Listed),
    subtract([ "getSimilarities(String, String)",
               "getDifferences(String, String)",
               "discriminate(Set)",
               "discriminateForAgent(String, Set)"
             ], Listed, Missing).
test(similarities_wire, true(Reply == ok("[\"? rdf:type Animal\",\"? eats grass\"]"))) :-
    cat_add_13_9(Add),
    cat_session([add-[Add]], getSimilarities, ["cow", "sheepy"], Reply).
test(similarities_cow_sheepy,
     true(V == ["? eats grass", "? rdf:type Animal"])) :-
    cat_similar("cow", "sheepy", V).
test(similarities_cow_gorilla,
     true(V == ["? age 12", "? isFemale false", "? rdf:type Animal"])) :-
    cat_similar("cow", "gorilla", V).
test(similarities_baboon_baboon2, true(V == ["? rdf:type Monkey"])) :-
    cat_similar("baboon", "baboon2", V).
test(similarities_f_j, true(V == ["? rdf:type B", "? rdf:type D"])) :-
    cat_similar("f", "j", V).
test(similarities_f_k, true(V == ["? rdf:type B", "? rdf:type D"])) :-
    cat_similar("f", "k", V).
test(similarities_f_e, true(V == ["? rdf:type E"])) :-
    cat_similar("f", "e", V).
test(similarities_f_f, true(V == ["? rdf:type F"])) :-
    cat_similar("f", "f", V).
test(similarities_prefixed, true(V == ["? eats grass", "? rdf:type Animal"])) :-
    cat_similar("oro:cow", "\"sheepy\"", V).
test(differences_cow_sheepy, true(V == [])) :-
    cat_differ("cow", "sheepy", V).
test(differences_wire, true(Reply == ok(Line))) :-
    Line = "[[\"cow rdf:type Animal\",\"gorilla rdf:type Monkey\",\c
            \"gorilla rdf:type MyAnimals\"],[\"cow eats grass\",\c
            \"gorilla eats apple\"],[\"cow weight 150.7\",\c
            \"gorilla weight 100.2\"]]",
    cat_add_13_9(Add),
    cat_session([add-[Add]], getDifferences, ["cow", "gorilla"], Reply).
test(differences_cow_gorilla,
     true(V == [ ["cow eats grass", "gorilla eats apple"],
                 ["cow rdf:type Animal", "gorilla rdf:type Monkey",
                  "gorilla rdf:type MyAnimals"],
                 ["cow weight 150.7", "gorilla weight 100.2"]
               ])) :-
    cat_differ("cow", "gorilla", V).
test(differences_baboon_baboon2,
     true(V == [["baboon age 35", "baboon2 age 75"]])) :-
    cat_add_13_9(Add),
    cat_session([add-[Add], add-["[baboon2 rdf:type MyAnimals]"]],
                 getDifferences, ["baboon", "baboon2"], Reply),
    cat_sorted(Reply, V).
test(differences_f_j, true(V == [ ["f rdf:type C", "j rdf:type J"],
                                  ["f rdf:type E", "j rdf:type I"]
                                ])) :-
    cat_differ("f", "j", V).
test(differences_f_k, true(V == [ ["f rdf:type C", "k rdf:type K"],
                                  ["f rdf:type E", "k rdf:type K"]
                                ])) :-
    cat_differ("f", "k", V).
test(differences_f_e, true(V == [["e rdf:type E", "f rdf:type F"]])) :-
    cat_differ("f", "e", V).
test(differences_f_f, true(V == [])) :-
    cat_differ("f", "f", V).
test(discriminate_capucin_gorilla,
     true(V == [[], ["age", "eats", "isFemale", "weight"]])) :-
    cat_discriminate_after(["[capucin rdf:type Monkey, capucin rdf:type MyAnimals]"],
                           "[capucin, gorilla]", V).
test(discriminate_wire, true(Reply == ok("[[\"eats\"],[\"eats\"]]"))) :-
    cat_session([ add-["[capucin rdf:type Monkey, capucin rdf:type MyAnimals]"],
                  add-["[capucin eats grass]"]
                ], discriminate, ["[capucin, gorilla]"], Reply).
test(discriminate_with_grass, true(V == [[], ["eats", "rdf:type"]])) :-
    cat_discriminate_after(["[capucin rdf:type Monkey, capucin rdf:type MyAnimals]",
                            "[capucin eats grass]"],
                           "[capucin, gorilla, grass]", V).
test(discriminate_colours, true(V == [["hasColor"], ["hasColor"]])) :-
    cat_discriminate_after(["[capucin rdf:type Monkey, capucin rdf:type MyAnimals]",
                            "[capucin eats grass]",
                            "[capucin hasColor grey, gorilla hasColor black, \c
                              grass hasColor green]"],
                           "[capucin, gorilla, grass]", V).
test(discriminate_climbs_on, true(V == [["climbsOn"], ["climbsOn"]])) :-
    cat_discriminate_after(["[capucin rdf:type Monkey, capucin rdf:type MyAnimals, \c
                              capucin climbsOn sunflower]"],
                           "[capucin, baboon]", V).
test(discriminate_vervet_macaque, true(V == [[], ["climbsOn"]])) :-
    cat_discriminate_after(["[vervet climbsOn palmtree, macaque rdf:type Monkey, \c
                              macaque isOn palmtree]"],
                           "[vervet, macaque]", V).
test(discriminate_vervet_macaque_coconut,
     true(V == [["climbsOn"], ["climbsOn"]])) :-
    cat_session([ add-["[vervet climbsOn palmtree, macaque rdf:type Monkey, \c
                         macaque isOn palmtree]"],
                  remove-["[macaque isOn palmtree]"],
                  add-["[macaque climbsOn coconut]"]
                ], discriminate, ["[vervet, macaque]"], Reply),
    cat_discriminate_value(Reply, V).
test(discriminate_seed, true(V == [[], ["hasColor"]])) :-
    cat_seed_statements(Statements),
    test_set_text(Statements, Add),
    cat_discriminate_after([Add], "[plant1, animal1, animal2, animal3]", V).
test(discriminate_empty, true(Reply == ok("[[],[]]"))) :-
    cat_session([], discriminate, ["[]"], Reply).
test(discriminate_for_myself, true(V == [["eats"], ["eats"]])) :-
    cat_session([ add-["[capucin rdf:type Monkey, capucin rdf:type MyAnimals, \c
                         capucin eats grass]"] ],
                discriminateForAgent, ["myself", "[capucin, gorilla]"], Reply),
    cat_discriminate_value(Reply, V).
test(discriminate_for_default, true(V == [["eats"], ["eats"]])) :-
    cat_session([ add-["[capucin rdf:type Monkey, capucin rdf:type MyAnimals, \c
                         capucin eats grass]"] ],
                discriminateForAgent, ["default", "[capucin, gorilla]"], Reply),
    cat_discriminate_value(Reply, V).
test(discriminate_for_agent, true(V == [["hasColor"], ["hasColor"]])) :-
    test_calls([reset-[]], _),
    oro_create_model(bob),
    oro_add(bob, ["x1 hasColor red", "x2 hasColor blue"]),
    test_calls([discriminateForAgent-["bob", "[x1, x2]"]], [Reply]),
    cat_discriminate_value(Reply, V).
test(discriminate_for_unknown_agent,
     true(Reply == error("laas.openrobots.ontology.exceptions.AgentNotFoundException",
                         "I couldn't find the agent nobody."))) :-
    cat_session([], discriminateForAgent, ["nobody", "[cow, gorilla]"], Reply).
test(similarities_instance_class,
     true(Reply == error("laas.openrobots.ontology.exceptions.NotComparableException",
                         "Can not compare resources of different kind \c
                          (a INSTANCE and a CLASS were provided)."))) :-
    cat_session([], getSimilarities, ["baboon", "Monkey"], Reply).
test(differences_instance_class,
     true(Reply == error("laas.openrobots.ontology.exceptions.NotComparableException",
                         "Can not compare resources of different kind \c
                          (a INSTANCE and a CLASS were provided)."))) :-
    cat_session([], getDifferences, ["baboon", "Monkey"], Reply).
test(similarities_two_classes,
     true(Reply == error("laas.openrobots.ontology.exceptions.NotComparableException",
                         "Only the comparison between instances \c
                          (individuals) is currently implemented"))) :-
    cat_session([], getSimilarities, ["Monkey", "Animal"], Reply).
test(similarities_unknown,
     true(Reply == error("com.hp.hpl.jena.shared.NotFoundException",
                         "Concept i_d_ont_exist doesn't exist in the ontology."))) :-
    cat_session([], getSimilarities, ["i_d_ont_exist", "cow"], Reply).
test(discriminate_unknown,
     true(Reply == error("com.hp.hpl.jena.shared.NotFoundException",
                         "Concept i_d_ont_exist doesn't exist in the ontology."))) :-
    cat_session([], discriminate, ["[cow, i_d_ont_exist]"], Reply).
test(wrong_parameter, true(Name == "NotImplementedException")) :-
    cat_session([], discriminate, ["cow"], error(Name, _)).

:- end_tests(categorization_protocol).


                 /*******************************
                 *     OTHER ONTOLOGIES         *
                 *******************************/

%   The seed example over the OpenRobots ontology alone: hasColor is
%   equivalent to mainColorOfObject and dbp:color, and below
%   hasFeature; discriminate lists the three equivalent properties, as
%   oro-server 0.8.2 does (hasFeature is strictly above them).

cat_start_openrobots :-
    cat_openrobots(File),
    test_server_start([commonsense(false), ontology(File)]).

cat_seed_add(Add) :-
    cat_seed_statements(Statements),
    test_set_text(Statements, Add).

cat_seed_discriminate(Set, V) :-
    cat_seed_add(Add),
    cat_discriminate_after([Add], Set, V).

:- begin_tests(categorization_openrobots,
               [ condition(cat_openrobots_available),
                 setup(cat_start_openrobots),
                 cleanup(cat_stop)
               ]).

test(seed_all, true(V == [[], Colours])) :-
    cat_colours(Colours),
    cat_seed_discriminate("[plant1, animal1, animal2, animal3]", V).
test(seed_coloured, true(V == [Colours, Colours])) :-
    cat_colours(Colours),
    cat_seed_discriminate("[plant1, animal2, animal3]", V).
test(seed_animals, true(V == [[], ["eats"|Colours]])) :-
    cat_colours(Colours),
    cat_seed_discriminate("[animal1, animal2, animal3]", V).
test(seed_similarities, true(V == ["? rdf:type owl:Thing"])) :-
    cat_seed_add(Add),
    cat_session([add-[Add]], getSimilarities, ["animal2", "plant1"], Reply),
    cat_sorted(Reply, V).
test(seed_differences,
     true(V == [ ["animal2 hasColor blue", "plant1 hasColor green"],
                 ["animal2 hasFeature blue", "plant1 hasFeature green"],
                 ["animal2 mainColorOfObject blue",
                  "plant1 mainColorOfObject green"],
                 ["animal2 rdf:type Animal", "plant1 rdf:type Plant"]
               ])) :-
    cat_seed_add(Add),
    cat_session([add-[Add]], getDifferences, ["animal2", "plant1"], Reply),
    cat_sorted(Reply, V).
test(seed_similar_animals, true(V == ["? rdf:type Animal"])) :-
    cat_seed_add(Add),
    cat_session([add-[Add]], getSimilarities, ["animal2", "animal3"], Reply),
    cat_sorted(Reply, V).

:- end_tests(categorization_openrobots).

cat_colours(["hasColor", "http://dbpedia.org/property/color", "mainColorOfObject"]).

%   The same property structure in a fixture of ours
%   (equivalent_properties.ttl): hue is equivalent to tint and ex:hue,
%   and below aspect.  discriminate lists the three equivalent
%   properties, through each of which the values are inferred, and not
%   aspect, strictly above them; getDifferences, over the default
%   namespace, shows aspect, hue and tint.

cat_start_equivalent :-
    test_fixture('equivalent_properties.ttl', File),
    test_server_start([commonsense(false), ontology(File)]).

cat_equivalent_add(Add) :-
    test_set_text([ "shrub1 rdf:type Shrub", "shrub1 hue green",
                    "beast1 rdf:type Beast", "beast1 feeds banana",
                    "beast2 rdf:type Beast", "beast2 feeds grass",
                    "beast2 hue blue",
                    "beast3 rdf:type Beast", "beast3 hue red"
                  ], Add).

cat_hues(["http://example.org/property/hue", "hue", "tint"]).

:- begin_tests(categorization_equivalent_properties,
               [ setup(cat_start_equivalent),
                 cleanup(cat_stop)
               ]).

test(all, true(V == [[], Hues])) :-
    cat_hues(Hues),
    cat_equivalent_add(Add),
    cat_discriminate_after([Add], "[shrub1, beast1, beast2, beast3]", V).
test(coloured, true(V == [Hues, Hues])) :-
    cat_hues(Hues),
    cat_equivalent_add(Add),
    cat_discriminate_after([Add], "[shrub1, beast2, beast3]", V).
test(for_agent, true(V == [Hues, Hues])) :-
    cat_hues(Hues),
    cat_equivalent_add(Add),
    cat_session([add-[Add]], discriminateForAgent,
                 [myself, "[shrub1, beast2, beast3]"], Reply),
    cat_discriminate_value(Reply, V).
test(beasts, true(V == [[], ["feeds"|Hues]])) :-
    cat_hues(Hues),
    cat_equivalent_add(Add),
    cat_discriminate_after([Add], "[beast1, beast2, beast3]", V).
test(differences,
     true(V == [ ["beast2 aspect blue", "shrub1 aspect green"],
                 ["beast2 hue blue", "shrub1 hue green"],
                 ["beast2 rdf:type Beast", "shrub1 rdf:type Shrub"],
                 ["beast2 tint blue", "shrub1 tint green"]
               ])) :-
    cat_equivalent_add(Add),
    cat_session([add-[Add]], getDifferences, ["beast2", "shrub1"], Reply),
    cat_sorted(Reply, V).
test(prolog, true(Total-Best == Hues-Hues)) :-
    Hues = [ 'http://example.org/property/hue',
             'http://kb.openrobots.org#hue',
             'http://kb.openrobots.org#tint'
           ],
    cat_equivalent_add(Add),
    test_call(reset, [], ok(_)),
    test_call(add, [Add], ok(_)),
    oro_discriminate(myself, [oro:shrub1, oro:beast2, oro:beast3], Total, Best).

:- end_tests(categorization_equivalent_properties).

%   The seed example over oro's own common-sense ontology.

cat_start_commonsense :-
    test_server_start([commonsense(true)]).

:- begin_tests(categorization_commonsense,
               [ setup(cat_start_commonsense),
                 cleanup(cat_stop)
               ]).

test(seed_all, true(V == [[], ["hasColor"]])) :-
    cat_seed_discriminate("[plant1, animal1, animal2, animal3]", V).
test(seed_coloured, true(V == [["hasColor"], ["hasColor"]])) :-
    cat_seed_discriminate("[plant1, animal2, animal3]", V).
test(seed_then_colour, true(V == [["hasColor"], ["hasColor"]])) :-
    cat_seed_discriminate("[animal2, animal3]", V).

:- end_tests(categorization_commonsense).
