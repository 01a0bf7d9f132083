:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for explanations (prolog/oro/questions/oro_explain.pl and the `explain`
    method of prolog/oro/server/oro_methods_explain.pl): the facts and axioms an
    entailed statement rests on, for each kind of inference; statements
    that do not hold; the minimal sets of facts in conflict of an
    inconsistent model; the reply format over the socket and its errors.

    Fixtures: test/fixtures/testsuite.ttl, test/fixtures/rl_classes.ttl,
    test/fixtures/rl_conflicts.ttl.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_explain.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).

ex_testsuite :-
    test_store_testsuite.

ex_rl(Statements) :-
    test_fixture('rl_classes.ttl', File),
    oro_init([commonsense(false), ontologies([File])]),
    oro_add(myself, Statements).

ex_conflicts(Statements) :-
    test_fixture('rl_conflicts.ttl', File),
    oro_init([commonsense(false), ontologies([File])]),
    oro_add(myself, Statements).

%   ex_explain(+Statement, -Facts, -Axioms): the explanation, facts and
%   axioms as sorted lists of contracted "S P O" texts; anonymous
%   classes are `_`.

ex_explain(Statement, Facts, Axioms) :-
    oro_explain(myself, Statement, explanation(_, Facts0, Axioms0)),
    findall(T, member(fact(T, _), Facts0), FactTriples),
    ex_texts(FactTriples, Facts),
    ex_texts(Axioms0, Axioms).

ex_texts(Triples, Texts) :-
    maplist(ex_text, Triples, Texts0),
    sort(Texts0, Texts).

ex_text(rdf(S, P, O), Text) :-
    maplist(ex_term, [S, P, O], Parts),
    atomic_list_concat(Parts, ' ', Text).

ex_term(T, '_') :-
    atom(T),
    rdf_is_bnode(T),
    !.
ex_term(T, Text) :-
    oro_term_text(T, Text).

%   ex_origins(+Statement, -Origins): the origins of its facts.

ex_origins(Statement, Origins) :-
    oro_explain(myself, Statement, explanation(_, Facts, _)),
    findall(O, member(fact(_, O), Facts), Origins).


                 /*******************************
                 *         RDFS AND OWL         *
                 *******************************/

:- begin_tests(explain_basic).

test(asserted, [ setup(ex_testsuite),
                 true(F-A == ['gorilla rdf:type Monkey']-[])
               ]) :-
    ex_explain("gorilla rdf:type Monkey", F, A).
test(origin_ontology, [ setup(ex_testsuite),
                        true(Origins = [ontology(_)])
                      ]) :-
    ex_origins("gorilla rdf:type Monkey", Origins).
test(origin_profiles, [ setup(ex_testsuite),
                        true(Origins == [profile(longterm), profile(shortterm)])
                      ]) :-
    oro_add(myself, ["rock1 isOn rock2"]),
    oro_add(myself, ["rock2 isOn rock3"], shortterm),
    ex_origins("rock1 isOn rock3", Origins0),
    msort(Origins0, Origins).
test(sub_class, [ setup(ex_testsuite),
                  true(F-A == ['gorilla rdf:type Monkey']-['Monkey rdfs:subClassOf Animal'])
                ]) :-
    ex_explain("gorilla rdf:type Animal", F, A).
test(sub_class_chain, [ setup(ex_testsuite),
                        true(A == ['C rdfs:subClassOf B', 'E rdfs:subClassOf C',
                                   'F rdfs:subClassOf E'])
                      ]) :-
    ex_explain("f rdf:type B", _, A).
test(range, [ setup(ex_testsuite),
              true(F-A == ['gorilla eats apple']-['eats rdfs:range Plant'])
            ]) :-
    ex_explain("apple rdf:type Plant", F, A).
test(domain_of_sub_property, [ setup(ex_testsuite),
                               true(F-A == ['bumbo climbsOn tree1']-
                                            ['climbsOn rdfs:subPropertyOf isOn',
                                             'isOn rdfs:domain Animal'])
                             ]) :-
    oro_add(myself, ["bumbo climbsOn tree1"]),
    ex_explain("bumbo rdf:type Animal", F, A).
test(inverse_of_sub_property, [ setup(ex_testsuite),
                                true(F-A == ['baboon climbsOn banana_tree']-
                                             ['climbsOn rdfs:subPropertyOf isOn',
                                              'isUnder owl:inverseOf isOn'])
                              ]) :-
    ex_explain("banana_tree isUnder baboon", F, A).
test(transitive, [ setup(ex_testsuite),
                   true(F-A == ['a1 isOn a2', 'a2 isOn a3', 'a3 isOn a4']-
                                ['isAt rdf:type owl:TransitiveProperty',
                                 'isOn rdfs:subPropertyOf isAt'])
                 ]) :-
    oro_add(myself, ["a1 isOn a2", "a2 isOn a3", "a3 isOn a4", "a2 isOn b9"]),
    ex_explain("a1 isAt a4", F, A).
test(same_as, [ setup(ex_testsuite),
                true(F == ['gorilla eats apple', 'kk owl:sameAs kong',
                           'kong owl:sameAs gorilla'])
              ]) :-
    oro_add(myself, ["kk owl:sameAs kong", "kong owl:sameAs gorilla"]),
    ex_explain("kk eats apple", F, _).
test(literal_by_value, [ setup(ex_testsuite),
                         true(F == ['gorilla age 12'])
                       ]) :-
    ex_explain(rdf(gorilla, age, 12), F, _).
test(not_entailed, [setup(ex_testsuite), fail]) :-
    oro_explain(myself, "gorilla rdf:type Plant", _).
test(pattern, [ setup(ex_testsuite),
                error(syntax_error(oro_statement_incomplete(_)))
              ]) :-
    oro_explain(myself, "?x eats apple", _).
test(unknown_agent, [ setup(ex_testsuite),
                      error(existence_error(agent, nobody))
                    ]) :-
    oro_explain(nobody, "gorilla rdf:type Monkey", _).

:- end_tests(explain_basic).


                 /*******************************
                 *       OWL 2 RL RULES         *
                 *******************************/

:- begin_tests(explain_rl).

test(has_value_type, [ setup(ex_rl(["ball hasColour red"])),
                       true(F-Key == ['ball hasColour red']-true)
                     ]) :-
    ex_explain("ball rdf:type RedObject", F, A),
    test_bool(( memberchk('RedObject owl:equivalentClass _', A),
                memberchk('_ owl:hasValue red', A),
                memberchk('_ owl:onProperty hasColour', A)
              ), Key).
test(has_value_edge, [ setup(ex_rl(["tom rdf:type Tomato"])),
                       true(F-Key == ['tom rdf:type Tomato']-true)
                     ]) :-
    ex_explain("tom hasColour red", F, A),
    test_bool(memberchk('Tomato rdfs:subClassOf _', A), Key).
test(some_values, [ setup(ex_rl(["carl owns rex", "rex rdf:type Puppy", "carl owns tom"])),
                    true(F-Key == ['carl owns rex', 'rex rdf:type Puppy']-true)
                  ]) :-
    ex_explain("carl rdf:type DogOwner", F, A),
    test_bool(memberchk('Puppy rdfs:subClassOf Dog', A), Key).
test(some_values_datatype, [ setup(ex_rl(["dan age 30"])),
                             true(F == ['dan age 30'])
                           ]) :-
    ex_explain("dan rdf:type Adult", F, _).
test(all_values, [ setup(ex_rl(["r1 rdf:type VeganRestaurant", "r1 serves salad"])),
                   true(F == ['r1 rdf:type VeganRestaurant', 'r1 serves salad'])
                 ]) :-
    ex_explain("salad rdf:type Dish", F, _).
test(intersection, [ setup(ex_rl(["ann rdf:type Woman", "ann hasChild bob"])),
                     true(F-Key == ['ann hasChild bob', 'ann rdf:type Woman']-true)
                   ]) :-
    ex_explain("ann rdf:type Mother", F, A),
    test_bool(( memberchk('_ owl:intersectionOf _', A),
                memberchk('_ rdf:first Woman', A),
                memberchk('_ rdf:first Parent', A)
              ), Key).
test(union, [ setup(ex_rl(["rex rdf:type Puppy"])),
              true(F-Key == ['rex rdf:type Puppy']-true)
            ]) :-
    ex_explain("rex rdf:type Pet", F, A),
    test_bool(memberchk('_ owl:unionOf _', A), Key).
test(one_of, [ setup(ex_rl([])),
               true(F-Key == []-true)
             ]) :-
    ex_explain("saturday rdf:type WeekendDay", F, A),
    test_bool(memberchk('_ owl:oneOf _', A), Key).
test(chain, [ setup(ex_rl(["x1 hasParent x2", "x2 hasParent x3", "x2 hasBrother x4"])),
              true(F-Key == ['x1 hasParent x2', 'x2 hasBrother x4']-true)
            ]) :-
    ex_explain("x4 hasNephew x1", F, A),
    test_bool(( memberchk('hasNephew owl:inverseOf hasUncle', A),
                memberchk('hasUncle owl:propertyChainAxiom _', A)
              ), Key).
test(cycle, [ setup(ex_rl(["l1 loops loopValue"])),
              true(F == ['l1 loops loopValue'])
            ]) :-
    ex_explain("l1 rdf:type Looped", F, _).
test(every_inference_explained,
     [ setup(ex_rl(["ball hasColour red", "tom rdf:type Tomato", "ann rdf:type Woman",
                    "ann hasChild bob", "carl owns rex", "rex rdf:type Puppy",
                    "x1 hasParent x2", "x2 hasParent x3", "x5 hasParent x2",
                    "r1 rdf:type VeganRestaurant", "r1 serves salad", "dan age 30",
                    "f1 follows f2", "f2 follows f3", "f3 follows f4"])),
       true(Unexplained == [])
     ]) :-
    rdf_equal(rdf:type, Type),
    findall(rdf(S, P, O),
            ( member(S0, [ball, tom, ann, bob, carl, rex, x1, x3, x5, salad, dan, f1]),
              oro_name_iri(S0, S),
              oro_holds(myself, S, P, O),
              (   P == Type
              ->  \+ rdf_is_bnode(O)
              ;   true
              )
            ), Triples),
    length(Triples, N),
    assertion(N > 40),
    include([T]>>oro_explain(myself, T, unexplained(_)), Triples, Unexplained).

:- end_tests(explain_rl).


                 /*******************************
                 *     TRANSITIVE, REFLEXIVE    *
                 *******************************/

%   `x P x` through a transitive property rests on the steps of a cycle
%   back to x, never on an empty path.

:- begin_tests(explain_transitive_cycle).

test(reflexive_through_cycle,
     [ setup(ex_conflicts(["e1 isBiggerThan e2", "e2 isBiggerThan e3",
                           "e3 isBiggerThan e1"])),
       true(F-A == ['e1 isBiggerThan e2', 'e2 isBiggerThan e3', 'e3 isBiggerThan e1']-
                   ['isBiggerThan rdf:type owl:TransitiveProperty'])
     ]) :-
    ex_explain("e1 isBiggerThan e1", F, A).
test(reflexive_asserted_loop,
     [ setup(ex_conflicts(["big1 isBiggerThan big1"])),
       true(F-A == ['big1 isBiggerThan big1']-[])
     ]) :-
    ex_explain("big1 isBiggerThan big1", F, A).
test(reflexive_through_sub_property_cycle,
     [ setup(ex_testsuite),
       true(F == ['c1 isOn c2', 'c2 isOn c1'])
     ]) :-
    oro_add(myself, ["c1 isOn c2", "c2 isOn c1"]),
    ex_explain("c1 isAt c1", F, _).
test(not_reflexive_without_cycle,
     [ setup(ex_conflicts(["e1 isBiggerThan e2", "e2 isBiggerThan e3"])),
       fail
     ]) :-
    oro_explain(myself, "e1 isBiggerThan e1", _).

:- end_tests(explain_transitive_cycle).


                 /*******************************
                 *          CONFLICTS           *
                 *******************************/

:- begin_tests(explain_conflicts).

%   ex_conflicts(-Conflicts): Kind-Facts pairs, facts as texts.

ex_conflict_texts(Pairs) :-
    oro_explain_conflict(myself, Conflicts),
    findall(K-Fs, ( member(conflict(C, Facts, _), Conflicts),
                    functor(C, K, _),
                    findall(T, member(fact(T, _), Facts), Ts),
                    ex_texts(Ts, Fs)
                  ), Pairs).

test(consistent, [ setup(ex_testsuite),
                   true(Cs == [])
                 ]) :-
    oro_explain_conflict(myself, Cs).
test(disjoint, [ setup(ex_testsuite),
                 true(Cs == [disjoint-['cow rdf:type Animal', 'cow rdf:type Plant']])
               ]) :-
    oro_add(myself, ["cow rdf:type Plant"]),
    ex_conflict_texts(Cs).
test(disjoint_axioms, [ setup(ex_testsuite),
                        true(As == ['Animal owl:disjointWith Plant'])
                      ]) :-
    oro_add(myself, ["cow rdf:type Plant"]),
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As).
test(minimal_among_supports, [ setup(ex_conflicts(["m1 rdf:type Rock", "m1 grows moss",
                                                   "m1 rdf:type Vegetable",
                                                   "m1 likes music"])),
                               true(Sizes == [2])
                             ]) :-
    ex_conflict_texts(Cs),
    findall(N, ( member(_-Fs, Cs), length(Fs, N) ), Sizes0),
    sort(Sizes0, Sizes).
test(irrelevant_facts_left_out, [ setup(ex_conflicts(["m1 rdf:type Rock", "m1 grows moss",
                                                      "m1 likes music", "m2 grows moss"])),
                                  true(Cs == [disjoint-['m1 grows moss',
                                                        'm1 rdf:type Rock']])
                                ]) :-
    ex_conflict_texts(Cs).
test(functional_with_difference, [ setup(ex_conflicts(["kid hasMother m1", "kid hasMother m2",
                                                       "m1 owl:differentFrom m2",
                                                       "kid hasMother m3"])),
                                   true(Cs == [functional-['kid hasMother m1',
                                                           'kid hasMother m2',
                                                           'm1 owl:differentFrom m2']])
                                 ]) :-
    ex_conflict_texts(Cs).
test(through_all_values, [ setup(ex_conflicts(["cellar1 rdf:type Cellar", "cellar1 stores t1",
                                               "t1 grows moss"])),
                           true(Cs == [disjoint-['cellar1 rdf:type Cellar',
                                                 'cellar1 stores t1', 't1 grows moss']])
                         ]) :-
    ex_conflict_texts(Cs).
test(same_as_variant_left_out, [ setup(ex_testsuite),
                                 true(Cs == [functional-['gorilla age 12', 'gorilla age 21']])
                               ]) :-
    oro_add(myself, ["kk owl:sameAs gorilla", "gorilla age 21"]),
    ex_conflict_texts(Cs).
test(one_conflict, [ setup(ex_testsuite),
                     true(Facts == ['cow rdf:type Animal', 'cow rdf:type Plant'])
                   ]) :-
    oro_add(myself, ["cow rdf:type Plant"]),
    rdf_equal(oro:cow, Cow),
    rdf_equal(oro:'Animal', Animal),
    rdf_equal(oro:'Plant', Plant),
    oro_explain_conflict(myself, disjoint(Cow, Animal, Plant), conflict(_, Fs, _)),
    findall(T, member(fact(T, _), Fs), Ts),
    ex_texts(Ts, Facts).

test(nothing, [ setup(ex_conflicts(["n0 rdf:type Genuine", "n1 rdf:type Impossible"])),
                true(Cs-Key == [nothing-['n1 rdf:type Impossible']]-true)
              ]) :-
    ex_conflict_texts(Cs),
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As),
    test_bool(memberchk('Impossible owl:equivalentClass owl:Nothing', As), Key).
test(inverse_functional, [ setup(ex_conflicts(["alice wears tag1", "beth wears tag1",
                                               "t3 wears tag2"])),
                           true(Cs == [inverse_functional-['alice wears tag1',
                                                           'beth wears tag1']])
                         ]) :-
    ex_conflict_texts(Cs).
test(inverse_functional_axioms, [ setup(ex_conflicts(["alice wears tag1",
                                                      "beth wears tag1"])),
                                  true(As == ['_ owl:distinctMembers _',
                                              '_ rdf:first alice', '_ rdf:first beth',
                                              '_ rdf:first carol', '_ rdf:rest _',
                                              '_ rdf:rest rdf:nil',
                                              '_ rdf:type owl:AllDifferent',
                                              'wears rdf:type owl:InverseFunctionalProperty'])
                                ]) :-
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As).
test(same_and_different, [ setup(ex_conflicts(["x1 owl:differentFrom y1",
                                               "x1 owl:sameAs y1", "x2 owl:sameAs y2"])),
                           true(Cs == [same_and_different-['x1 owl:differentFrom y1',
                                                           'x1 owl:sameAs y1']])
                         ]) :-
    ex_conflict_texts(Cs).
test(irreflexive_asserted, [ setup(ex_conflicts(["big1 isBiggerThan small1",
                                                 "big1 isBiggerThan big1"])),
                             true(Cs-As == [irreflexive-['big1 isBiggerThan big1']]-
                                           ['isBiggerThan rdf:type owl:IrreflexiveProperty'])
                           ]) :-
    ex_conflict_texts(Cs),
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As).
test(irreflexive_through_cycle, [ setup(ex_conflicts(["e1 isBiggerThan e2",
                                                      "e2 isBiggerThan e3",
                                                      "e3 isBiggerThan e1",
                                                      "e3 isBiggerThan e4"])),
                                  true(Sets-Axioms ==
                                       [['e1 isBiggerThan e2', 'e2 isBiggerThan e3',
                                         'e3 isBiggerThan e1']]-
                                       ['isBiggerThan rdf:type owl:IrreflexiveProperty',
                                        'isBiggerThan rdf:type owl:TransitiveProperty'])
                                ]) :-
    oro_explain_conflict(myself, Conflicts),
    findall(Fs, ( member(conflict(irreflexive(_, _), Facts, _), Conflicts),
                  findall(T, member(fact(T, _), Facts), Ts),
                  ex_texts(Ts, Fs)
                ), Sets0),
    sort(Sets0, Sets),
    findall(A, ( member(conflict(irreflexive(_, _), _, As0), Conflicts),
                 ex_texts(As0, As),
                 member(A, As)
               ), Axioms0),
    sort(Axioms0, Axioms).
test(irreflexive_each_of_the_cycle, [ setup(ex_conflicts(["e1 isBiggerThan e2",
                                                          "e2 isBiggerThan e3",
                                                          "e3 isBiggerThan e1"])),
                                      true(Sizes == [3, 3, 3])
                                    ]) :-
    rdf_equal(oro:isBiggerThan, P),
    findall(N, ( member(X0, [e1, e2, e3]),
                 oro_name_iri(X0, X),
                 oro_explain_conflict(myself, irreflexive(P, X), conflict(_, Fs, _)),
                 length(Fs, N)
               ), Sizes).
test(asymmetric, [ setup(ex_conflicts(["a1 isParentOf b1", "b1 isParentOf a1",
                                       "b1 isParentOf c1"])),
                   true(Cs-As == [asymmetric-['a1 isParentOf b1', 'b1 isParentOf a1']]-
                                 ['isParentOf rdf:type owl:AsymmetricProperty'])
                 ]) :-
    ex_conflict_texts(Cs),
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As).
test(disjoint_properties, [ setup(ex_conflicts(["ann adores coffee", "ann hates coffee",
                                                "ann hates tea"])),
                            true(Cs-As == [disjoint_properties-['ann adores coffee',
                                                                'ann hates coffee']]-
                                          ['adores rdfs:subPropertyOf likes',
                                           'likes owl:propertyDisjointWith hates'])
                          ]) :-
    ex_conflict_texts(Cs),
    oro_explain_conflict(myself, [conflict(_, _, Axioms)]),
    ex_texts(Axioms, As).

:- end_tests(explain_conflicts).


                 /*******************************
                 *          PROTOCOL            *
                 *******************************/

:- begin_tests(explain_protocol,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

ex_fresh :-
    test_ok(reset, []).

ex_call(Params, Value) :-
    test_ok(explain, Params, Line),
    test_json(Line, Value).

test(entailed_and_not,
     [ setup(ex_fresh),
       true(Value == [ [ "asserted"-["gorilla rdf:type Monkey"],
                         "axioms"-["Monkey rdfs:subClassOf Animal"],
                         "entailed"-true,
                         "statement"-"gorilla rdf:type Animal"
                       ],
                       [ "entailed"-false,
                         "statement"-"gorilla rdf:type Plant"
                       ]
                     ])
     ]) :-
    ex_call(['[gorilla rdf:type Animal, gorilla rdf:type Plant]'], Value).
test(literal_light_form,
     [ setup(ex_fresh),
       true(Asserted == ["gorilla age 12"])
     ]) :-
    ex_call(['[gorilla age 12]'], [Map]),
    memberchk("asserted"-Asserted, Map).
test(conflicts_while_inconsistent,
     [ setup(ex_fresh),
       true(Value == [ [ "about"-["cow", "Animal", "Plant"],
                         "asserted"-["cow rdf:type Animal", "cow rdf:type Plant"],
                         "axioms"-["Animal owl:disjointWith Plant"],
                         "conflict"-"disjoint"
                       ]
                     ])
     ]) :-
    test_ok(add, ['[cow rdf:type Plant]']),
    ex_call(['[]'], Value).
test(empty_when_consistent, [ setup(ex_fresh),
                              true(Value == "[]")
                            ]) :-
    test_ok(explain, ['[]'], Value).
test(pattern_is_an_error,
     [ setup(ex_fresh),
       true(Name == "laas.openrobots.ontology.exceptions.IllegalStatementException")
     ]) :-
    test_call(explain, ['[?x eats apple]'], Reply),
    test_error_name(Reply, Name).
test(malformed_is_an_error,
     [ setup(ex_fresh),
       true(Name == "laas.openrobots.ontology.exceptions.IllegalStatementException")
     ]) :-
    test_call(explain, ['[gorilla eats]'], Reply),
    test_error_name(Reply, Name).
test(listed, [ true(memberchk("explain(Set)", Signatures)) ]) :-
    test_set_call(listSimpleMethods, [], Signatures).

:- end_tests(explain_protocol).

:- begin_tests(explain_protocol_classes,
               [ setup(ex_rl_server),
                 cleanup(test_server_stop)
               ]).

ex_rl_server :-
    test_fixture('rl_classes.ttl', File),
    test_server_start([commonsense(false), ontology(File)]).

test(anonymous_classes_inline,
     [ setup(test_ok(reset, [])),
       true(Axioms == ["Mother owl:equivalentClass (Woman and Parent)",
                       "Parent owl:equivalentClass (hasChild some owl:Thing)"])
     ]) :-
    test_ok(add, ['[ann rdf:type Woman, ann hasChild bob]']),
    test_ok(explain, ['[ann rdf:type Mother]'], Line),
    test_json(Line, [Map]),
    memberchk("axioms"-Axioms0, Map),
    msort(Axioms0, Axioms).
test(restrictions_inline,
     [ setup(test_ok(reset, [])),
       true(Axioms == ["Adult owl:equivalentClass (age some xsd:integer[>= 18])"])
     ]) :-
    test_ok(add, ['[dan age 30]']),
    test_ok(explain, ['[dan rdf:type Adult]'], Line),
    test_json(Line, [Map]),
    memberchk("axioms"-Axioms, Map).
test(chain_inline,
     [ setup(test_ok(reset, [])),
       true(Axioms == ["hasSibling owl:propertyChainAxiom (hasParent (inverse hasParent))"])
     ]) :-
    test_ok(add, ['[x1 hasParent x2, x5 hasParent x2]']),
    test_ok(explain, ['[x1 hasSibling x5]'], Line),
    test_json(Line, [Map]),
    memberchk("axioms"-Axioms, Map).

:- end_tests(explain_protocol_classes).
