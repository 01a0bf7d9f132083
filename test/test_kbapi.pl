:- use_module(library(plunit)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(http/json)).
:- use_module(oro_test_support).
:- use_module(oro_test_client).
:- use_module(kb_test_client).
:- use_module(library(oro)).
:- use_module(library(oro/oro_memory), [oro_memory_sync/0]).
:- use_module(library(oro/kbapi/oro_kbapi_events), [kb_events_sync/0]).

/*  The KB-API dialect (knowledge_core, minimalkb, pykb) over a real
    socket: prolog/oro/kbapi/oro_kbapi.pl and its methods.

    The scenarios are those knowledge_core's socket test suite
    (testing/test.py, test_reasoner.py) describes, written from its
    public API description: basics and malformed statements, literals,
    modifications, models, complex queries, update of functional
    properties, retrieval, lookup, events from one and several clients,
    polled events with bindings of several variables, one-shot events,
    RDFS and taxonomy walking, lifespans.  Where oro answers more than
    knowledge_core without a reasoner (owl:Thing, reflexive
    subClassOf: oro answers from the inference closure) the tests say
    what must be in the answer rather than its exact size.

    Absence of an event is checked after kb_events_sync/0 (the change
    was evaluated) and a short wait for the connection's writer: such a
    check passes however slow the machine; arrivals are waited for (10
    s at most).  Lifespans are driven by the memory module's test
    clock, never by waiting.
*/

kb_start :-
    test_server_start([commonsense(false), kb_port(0)]).

kb_stop :-
    test_server_stop.

%   kb(-Conn, :Goal): Goal on a new KB-API connection.

:- meta_predicate kb(-, 0).

kb(Conn, Goal) :-
    test_server_kb_port(Port),
    setup_call_cleanup(kb_connect(Port, Conn),
                       once(Goal),
                       kb_disconnect(Conn)).

ok(Conn, Method, Args) :-
    kb_call(Conn, Method, Args, Reply),
    assertion(Reply == ok).

ok(Conn, Method, Args, Value) :-
    kb_call(Conn, Method, Args, Reply),
    (   Reply = ok(Value0)
    ->  Value = Value0
    ;   Reply == ok
    ->  Value = null
    ;   format(user_error, "~w ~q: ~q~n", [Method, Args, Reply]),
        fail
    ).

%   q(+Conn, +Patterns, -Rows): pykb's kb[...] (knowledge_core's
%   find(patterns)), rows sorted.

q(Conn, Patterns, Rows) :-
    ok(Conn, find, [Patterns], Rows0),
    msort(Rows0, Rows).

is_error(Conn, Method, Args) :-
    kb_call(Conn, Method, Args, Reply),
    Reply = error("kberror", _).

no_event(Conn) :-
    kb_events_sync,
    kb_no_event(Conn, 0.2).

event(Conn, Id, Value) :-
    kb_next_event(Conn, event(Id, Value), 10).

sorted(Value, Sorted) :-
    msort(Value, Sorted).

error_bool(C, Method-Args, Bool) :-
    test_bool(is_error(C, Method, Args), Bool).

literal_kind(C, Prefix, Kind, Value, Bool, I0, I) :-
    I is I0 + 1,
    format(string(P), "~w~w", [Prefix, I]),
    format(string(S), "robert ~w ~w", [P, Value]),
    ok(C, update, [[S]]),
    ok(C, lookup, [P], Found),
    test_bool(Found == [[P, Kind]], Bool).

malformed(C, Value, Bool) :-
    format(string(S), "robert relbad ~w", [Value]),
    test_bool(is_error(C, update, [[S]]), Bool).

is_error_bool(C, Method, Args, Bool) :-
    test_bool(is_error(C, Method, Args), Bool).


                 /*******************************
                 *            BASICS            *
                 *******************************/

:- begin_tests(kbapi_basics, [setup(kb_start), cleanup(kb_stop)]).

test(hello, true(Sub =@= true)) :-
    kb(C, ok(C, hello, [], Hello)),
    test_bool(sub_string(Hello, _, _, _, "oro"), Sub).
test(methods_listed, true(Missing =@= [])) :-
    kb(C, ok(C, methods, [], Methods)),
    findall(M, ( member(M, [hello, methods, about, lookup, label, details,
                            classesof, exist, find, revise, add, update,
                            retract, remove, subscribe, sparql, load, save,
                            clear, close, check_consistency, safe_add,
                            explain, similarities, differences,
                            discriminate]),
                 \+ ( member(T, Methods),
                      atom_concat(M, '(', Prefix),
                      sub_atom(T, 0, _, _, Prefix)
                    )
               ), Missing).
test(malformed, true(Errors =@= [true, true, true, true, true, true])) :-
    kb(C, ( maplist(error_bool(C),
                    [ add-[], add-["toto"], add-[["toto"]],
                      update-[["toto"]], update-[["toto titi"]],
                      update-[["toto titi tutu tata"]]
                    ], Errors) )).
test(bad_json_keeps_connection, true(r(E, V) =@= r(true, true))) :-
    kb(C, ( kb_send_raw(C, "add\n[\"a b c\"\n#end#\n"),
            kb_receive(C, R, 10),
            test_bool(R = error("kberror", _), E),
            kb_call(C, exist, [["a b c"]], V0),
            test_bool(V0 == ok(false), V)
          )).
test(bad_batch_changes_nothing, true(V =@= ok(false))) :-
    kb(C, ( is_error(C, add, [["good one two", "bad"]]),
            kb_call(C, exist, [["good one two"]], V) )).
test(unknown_method, true(E =@= true)) :-
    kb(C, test_bool(is_error(C, frobnicate, []), E)).
test(modifications) :-
    kb(C, ( ok(C, add, [["johnny rdf:type Human", "johnny rdfs:label \"A que Johnny\""]]),
            ok(C, update, [["alfred rdf:type Human", "alfred likes icecream"]]),
            ok(C, remove, [["alfred rdf:type Human", "alfred likes icecream"]]),
            ok(C, retract, [["johnny rdf:type Human"]]),
            ok(C, revise, [["toto likes tata"], _{method:"add"}])
          )).
test(models_modifications, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( ok(C, add, [["johnny rdf:type Human"], ["model1"]]),
            ok(C, remove, [["alfred likes icecream"], ["model1", "model2"]]),
            ok(C, revise, [["toto likes tata"], _{method:"add", models:["model1", "model2"]}]),
            ok(C, exist, [["toto likes tata"], ["model1", "model2"]], A),
            ok(C, exist, [["johnny rdf:type Human"], ["model1"]], B)
          )).
test(kwargs, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( kb_call(C, revise, [["toto likes tata"]], _{policy:_{method:"add"}}, ok),
            kb_call(C, add, [["johnny rdf:type Human"]], _{lifespan:10}, ok),
            ok(C, exist, [["toto likes tata"]], A),
            ok(C, exist, [["johnny rdf:type Human"]], B)
          )).
test(close_without_reply, true(R =@= end_of_file)) :-
    kb(C, ( kb_send_raw(C, "close\n#end#\n"),
            kb_receive(C, R, 10) )).


:- end_tests(kbapi_basics).

                 /*******************************
                 *        QUERIES, MODELS       *
                 *******************************/

:- begin_tests(kbapi_queries, [setup(kb_start), cleanup(kb_stop)]).

test(star_star_star, true(r(In, Out) =@= r(true, false))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["alfred rdf:type Human"]]),
            q(C, ["?__1 ?__2 ?__3"], Rows1),
            test_bool(memberchk(_{var1:"alfred", var2:"rdf:type", var3:"Human"}, Rows1), In),
            ok(C, retract, [["alfred rdf:type Human"]]),
            q(C, ["?__1 ?__2 ?__3"], Rows2),
            test_bool(memberchk(_{var1:"alfred", var2:"rdf:type", var3:"Human"}, Rows2), Out)
          )).
test(existence, true(L =@= [false, false, true, true, false, true, true, true,
                          true, false, false, false, false])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, exist, [["alfred likes icecream"]], A1),
            ok(C, exist, [["alfred likes ?x"]], A2),
            ok(C, update, [["alfred rdf:type Human", "alfred likes icecream"]]),
            ok(C, exist, [["alfred likes icecream"]], A3),
            is_error_bool(C, exist, [["alfred likes"]], A4),
            ok(C, exist, [["alfred likes mygrandmother"]], A5),
            ok(C, exist, [["alfred likes ?smthg"]], A6),
            ok(C, exist, [["?a likes ?b"]], A7),
            ok(C, exist, [["?toto likes ?__x"]], A8),
            ok(C, lookup, ["alfred"], L9), test_bool(L9 \== [], A9),
            ok(C, exist, [["?a dislikes ?b"]], A10),
            ok(C, lookup, ["tartempion"], L11), test_bool(L11 \== [], A11),
            ok(C, retract, [["alfred rdf:type Human", "alfred likes icecream"]]),
            ok(C, exist, [["alfred likes icecream"]], A12),
            ok(C, lookup, ["alfred"], L13), test_bool(L13 \== [], A13),
            L = [A1, A2, A3, A4, A5, A6, A7, A8, A9, A10, A11, A12, A13]
          )).
test(lookup, true(L =@= [ [], [["Robot", "class"]], [["likes", "object_property"]],
                         [["alfred", "instance"]],
                         [["alfred", "instance"], ["nono", "instance"]],
                         [["\"likes\"", "literal"]],
                         [["age", "datatype_property"]],
                         [["rdf:type", "object_property"]] ])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, lookup, ["alfred"], L1),
            ok(C, update, [["alfred rdf:type Robot", "alfred likes icecream"]]),
            ok(C, lookup, ["Robot"], L2),
            ok(C, lookup, ["likes"], L3),
            ok(C, lookup, ["alfred"], L4),
            ok(C, update, [["nono rdfs:label \"alfred\"", "nono rdf:type Human"]]),
            ok(C, lookup, ["alfred"], L5),
            ok(C, update, [["gerard rdfs:label \"likes\""]]),
            ok(C, lookup, ["\"likes\""], L6),
            ok(C, update, [["gerard age 18"]]),
            ok(C, lookup, ["age"], L7),
            ok(C, lookup, ["rdf:type"], L8),
            L = [L1, L2, L3, L4, L5, L6, L7, L8]
          )).
test(literals, true(r(Data, Objects, Malformed) =@= r(Ones, [true, true, true], [true, true]))) :-
    Literals = [ "\"test\"", "\"\"\"test\"\"\"", "\"test\"@fr",
                 "\"foo\"^^<http://example.org/my/datatype>",
                 "\"10\"^^xsd:decimal", "-5", "0", "1", "10", "+1",
                 "\"-5\"^^xsd:integer",
                 "\"10\"^^<http://www.w3.org/2001/XMLSchema#integer>",
                 "1.3e2", "10e0", "-12.5e10", "\"1.3e2\"^^xsd:double",
                 "0.0", "1.0", "1.234567890123456789", "-5.0",
                 "\"0.0\"^^xsd:decimal", "true", "false",
                 "\"true\"^^xsd:boolean"
               ],
    length(Literals, N),
    length(Ones, N),
    maplist(=(true), Ones),
    kb(C, ( ok(C, clear, []),
            foldl(literal_kind(C, rel, "datatype_property"), Literals, Data, 0, _),
            foldl(literal_kind(C, relobj, "object_property"), ["test", "False", "True"],
                  Objects, 0, _),
            maplist(malformed(C), ["\"test\"^^", "\"\"\"a"], Malformed)
          )).
test(retrieval, true(r(About, Found1, Found2, Holds) =@=
                     r(true, [_{var1:"alfred"}, _{var1:"johnny"}], [_{var1:"johnny"}],
                       ["johnny rdf:type Human"]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["johnny rdf:type Human", "johnny rdfs:label \"A que Johnny\""]]),
            ok(C, update, [["alfred rdf:type Human", "alfred likes icecream"]]),
            ok(C, about, ["Human"], Triples),
            test_bool(( memberchk(["johnny", "rdf:type", "Human"], Triples),
                        memberchk(["alfred", "rdf:type", "Human"], Triples) ), About),
            q(C, ["?__x rdf:type Human"], Found1),
            ok(C, retract, [["alfred rdf:type Human", "alfred likes icecream"]]),
            q(C, ["?__x rdf:type Human"], Found2),
            ok(C, find, [["johnny rdf:type Human"]], Holds)
          )).
test(models_retrieval, true(L =@= [["s p o"], ["s2 p2 o2"], ["s p o"], [], [], true, false])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, add, [["s p o", "s2 p2 o2"], ["model1", "model2"]]),
            ok(C, find, [["s p o"], null, ["model1"]], A),
            ok(C, find, [["s2 p2 o2"], null, ["model1"]], B),
            kb_call(C, find, [["s p o"]], _{models:["model2"]}, ok(D0)),
            D = D0,
            ok(C, find, [["s p o"]], E),
            ok(C, about, ["s", ["myself"]], F),
            ok(C, exist, [["s p o"], ["model1", "model2"]], G),
            ok(C, exist, [["s p o"], ["all"]], H),
            L = [A, B, D, E, F, G, H]
          )).
test(about_models, true(r(A, B) =@= r(true, false))) :-
    kb(C, ( ok(C, add, [["nono isNice true"], ["model1"]]),
            ok(C, add, [["jamesbond isNice true"], ["model2"]]),
            ok(C, about, ["nono", ["model1"]], T1), test_bool(T1 \== [], A),
            ok(C, about, ["nono", ["model2"]], T2), test_bool(T2 \== [], B)
          )).
test(complex_queries, true(L =@= [ [], [_{agent:"nono"}], [_{agent:"nono"}],
                                  [_{agent:"alfred", obj:"oil"}],
                                  [_{act:"jump", agent:"nono"}],
                                  [_{agent:"alfred", obj:"oil"}, _{agent:"nono", obj:"jump"}] ])) :-
    kb(C, ( ok(C, clear, []),
            q(C, ["?agent rdf:type Robot", "?agent desires ?obj"], L1),
            ok(C, update, [["nono rdf:type Human", "alfred rdf:type Robot"]]),
            ok(C, update, [["nono desires jump", "alfred desires oil"]]),
            ok(C, update, [["nono loves icecream"]]),
            q(C, ["?agent desires jump", "?agent loves icecream"], L2),
            q(C, ["?agent desires ?__a", "?agent loves icecream"], L3),
            ok(C, update, [["jump rdf:type Action"]]),
            q(C, ["?agent rdf:type Robot", "?agent desires ?obj"], L4),
            q(C, ["?agent desires ?act", "?act rdf:type Action"], L5),
            q(C, ["?agent desires ?obj"], L6),
            L = [L1, L2, L3, L4, L5, L6]
          )).
test(minimalkb_find, true(r(V, R) =@= r(["alfred", "nono"],
                                       [_{a:"alfred", o:"oil"}, _{a:"nono", o:"jump"}]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["nono desires jump", "alfred desires oil"]]),
            ok(C, find, [["?a"], ["?a desires ?o"]], V0), msort(V0, V),
            ok(C, find, [["?a", "?o"], ["?a desires ?o"], null, null], R0), msort(R0, R)
          )).
test(find_constraints, true(V =@= ["bob"])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["bob age 40", "tim age 12"]]),
            ok(C, find, [["?x"], ["?x age ?a"], ["?a > 18"]], V)
          )).
test(update_functional, true(r(A, B, D) =@= r([_{var1:"nono"}], [], [_{var1:"nono"}]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["nono isNice true", "isNice rdf:type owl:FunctionalProperty"]]),
            q(C, ["?__x isNice true"], A),
            ok(C, update, [["nono isNice false"]]),
            q(C, ["?__x isNice true"], B),
            q(C, ["?__x isNice false"], D)
          )).
test(label_details, true(r(L, Type, Classes) =@=
                         r(_{default:"A que Johnny", fr:"Jojo"}, "instance", true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["johnny rdf:type Human", "johnny rdfs:label \"A que Johnny\"",
                            "johnny rdfs:label \"Jojo\"@fr"]]),
            ok(C, label, ["johnny"], L),
            ok(C, details, ["johnny"], D),
            get_dict(type, D, Type),
            get_dict(attributes, D, Attributes),
            test_bool(( member(A, Attributes), get_dict(id, A, "classes"),
                        get_dict(values, A, Values),
                        memberchk(_{id:"Human", label:"Human"}, Values) ), Classes)
          )).
test(sparql_json, true(r(Vars, Type, Value) =@= r(["age"], "literal", "40"))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["myself age 40"]]),
            ok(C, sparql, ["SELECT ?age WHERE { :myself :age ?age . }"], R),
            get_dict(head, R, Head),
            get_dict(vars, Head, Vars),
            get_dict(results, R, Results),
            get_dict(bindings, Results, [Row]),
            get_dict(age, Row, Age),
            get_dict(type, Age, Type),
            get_dict(value, Age, Value)
          )).
test(sparql_error, true(E =@= true)) :-
    kb(C, test_bool(is_error(C, sparql, ["SELECT ?x WHERE {"]), E)).

:- end_tests(kbapi_queries).

                 /*******************************
                 *            EVENTS            *
                 *******************************/

:- begin_tests(kbapi_events, [setup(kb_start), cleanup(kb_stop)]).

test(events, true(r(N1, E1, N2, N3, N4, E2) =@=
                  r(true, [_{o:"alfred"}], true, true, true, [_{o:"batman"}]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, [["?o isIn room"]], Id),
            ok(C, update, [["alfred isIn garage"]]),
            test_bool(no_event(C), N1),
            ok(C, update, [["alfred isIn room"]]),
            event(C, Id, E1),
            ok(C, update, [["alfred leaves room"]]),
            test_bool(no_event(C), N2),
            ok(C, subscribe, [["?o isIn garage"]], Id2),
            assertion(Id2 \== Id),
            test_bool(no_event(C), N3),
            ok(C, update, [["alfred isIn garage"]]),
            test_bool(no_event(C), N4),
            ok(C, update, [["batman isIn garage"]]),
            event(C, Id2, E2)
          )).
test(events_multiclients, true(r(N, E) =@= r(true, [_{o:"alfred"}]))) :-
    kb(C, kb(C2, ( ok(C, clear, []),
                   ok(C, subscribe, [["?o isIn room"]], Id),
                   ok(C2, update, [["alfred isIn garage"]]),
                   test_bool(no_event(C), N),
                   ok(C2, update, [["alfred isIn room"]]),
                   event(C, Id, E)
                 ))).
test(same_subscription_shared, true(r(Id1, E1, E2) =@= r(Id2, [_{o:"alfred"}], [_{o:"alfred"}]))) :-
    kb(C, kb(C2, ( ok(C, clear, []),
                   ok(C, subscribe, [["?o isIn room"]], Id1),
                   ok(C2, subscribe, [["?o isIn room"]], Id2),
                   ok(C, update, [["alfred isIn room"]]),
                   event(C, Id1, E1),
                   event(C2, Id2, E2)
                 ))).
test(complex_events, true(r(N1, N2, E) =@= r(true, true, [_{a:"alfred", act:"ragnagna"}]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, [["?a desires ?act", "?act rdf:type Action"]], Id),
            ok(C, update, [["alfred desires ragnagna"]]),
            test_bool(no_event(C), N1),
            ok(C, update, [["ragnagna rdf:type Zorro"]]),
            test_bool(no_event(C), N2),
            ok(C, update, [["ragnagna rdf:type Action"]]),
            event(C, Id, E)
          )).
test(complex_events_rdfs, true(r(N, E) =@= r(true, ["alfred"]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, ["NEW_INSTANCE", "ON_TRUE", "?a",
                              ["?a desires ?act", "?act rdf:type Action"], null], Id),
            ok(C, update, [["alfred desires ragnagna", "ragnagna rdf:type Zorro"]]),
            test_bool(no_event(C), N),
            ok(C, update, [["Zorro rdfs:subClassOf Action"]]),
            event(C, Id, E)
          )).
test(one_shot, true(r(E, N) =@= r([_{o:"alfred"}], true))) :-
    kb(C, ( ok(C, clear, []),
            kb_call(C, subscribe, [["?o isIn room"]], _{one_shot:true}, ok(Id)),
            ok(C, update, [["alfred isIn room"]]),
            event(C, Id, E),
            ok(C, update, [["batman isIn room"]]),
            test_bool(no_event(C), N)
          )).
test(new_class_instance_one_shot, true(r(E, N) =@= r(["alfred"], true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, ["NEW_CLASS_INSTANCE_ONE_SHOT", "ON_TRUE", null, ["Robot"]], Id),
            ok(C, update, [["alfred rdf:type Robot"]]),
            event(C, Id, E),
            ok(C, update, [["r2d2 rdf:type Robot"]]),
            test_bool(no_event(C), N)
          )).
test(events_of_a_model, true(r(N, E) =@= r(true, [_{o:"alfred"}]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, [["?o isIn room"], false, ["bob"]], Id),
            ok(C, update, [["alfred isIn room"]]),
            test_bool(no_event(C), N),
            ok(C, update, [["alfred isIn room"], ["bob"]]),
            event(C, Id, E)
          )).
test(event_from_oro_client, true(E =@= [_{o:"alfred"}])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, [["?o isIn room"]], Id),
            test_call(add, ["[alfred isIn room]"], ok(_)),
            event(C, Id, E)
          )).
test(closed_client_unsubscribed, true(N =@= true)) :-
    kb(C0, ( ok(C0, clear, []),
             ok(C0, subscribe, [["?o isIn room"]], _) )),
    kb(C, ( ok(C, update, [["alfred isIn room"]]),
            test_bool(no_event(C), N) )).
test(bad_subscription, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( test_bool(is_error(C, subscribe, [["?o isIn"]]), A),
            test_bool(is_error(C, subscribe, ["NEW_THING", "ON_TRUE", "?o", ["?o a b"]]), B)
          )).

:- end_tests(kbapi_events).

                 /*******************************
                 *      RDFS, TAXONOMY, ORO     *
                 *******************************/

:- begin_tests(kbapi_reasoning, [setup(kb_start), cleanup(kb_stop)]).

test(new_model_reasons, true(r(A, B) =@= r(true, false))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, add, [["s p o"], ["model1"]]),
            ok(C, exist, [["s rdf:type owl:Thing"], ["model1"]], A),
            ok(C, exist, [["s rdf:type owl:Thing"], ["model2"]], B) )).
test(taxonomy_walking, true(L =@= [[], true, ["Human"], ["Genius", "Human"], ["Genius"]])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, classesof, ["john"], L1),
            ok(C, update, [["john rdf:type Human"]]),
            ok(C, classesof, ["john"], L2a),
            test_bool(memberchk("Human", L2a), L2),
            ok(C, classesof, ["john", true], L3),
            ok(C, update, [["john rdf:type Genius"]]),
            ok(C, classesof, ["john", true], L4),
            ok(C, retract, [["john rdf:type Human"]]),
            kb_call(C, classesof, ["john"], _{direct:true}, ok(L5)),
            L = [L1, L2, L3, L4, L5]
          )).
test(inheritance, true(r(A, D, G) =@= r(true, ["Human"], true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["john rdf:type Human", "Human rdfs:subClassOf Animal"]]),
            ok(C, classesof, ["john"], All),
            test_bool(subset(["Human", "Animal"], All), A),
            ok(C, classesof, ["john", true], D),
            ok(C, retract, [["john rdf:type Human"]]),
            ok(C, classesof, ["john"], Gone),
            test_bool(\+ memberchk("Animal", Gone), G)
          )).
test(second_level, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["myself rdf:type Robot", "Robot rdfs:subClassOf Agent",
                            "Agent rdfs:subClassOf PhysicalEntity"]]),
            ok(C, exist, [["Robot rdfs:subClassOf PhysicalEntity"]], A),
            ok(C, exist, [["myself rdf:type PhysicalEntity"]], B) )).
%   knowledge_core's OWL RL reasoner also entails "Robot
%   owl:equivalentClass Automaton" itself; oro's reasoner derives what
%   equivalence means (the classes, the sub-classes) but not that
%   statement.

test(equivalent_classes, true(r(B, D) =@= r(true, true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["myself rdf:type Robot", "Robot owl:equivalentClass Machine",
                            "Machine owl:equivalentClass Automaton",
                            "PR2 rdfs:subClassOf Automaton"]]),
            ok(C, classesof, ["myself"], Cs),
            test_bool(subset(["Robot", "Machine", "Automaton"], Cs), B),
            ok(C, exist, [["PR2 rdfs:subClassOf Robot"]], D) )).
test(existence_with_inference, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["alfred rdf:type Human", "Human rdfs:subClassOf Animal"]]),
            ok(C, exist, [["alfred rdf:type Animal"]], A),
            ok(C, update, [["Animal rdfs:subClassOf Thing"]]),
            ok(C, exist, [["alfred rdf:type Thing"]], B) )).
test(consistency_and_safe_add, true(r(A, Ok, Kept, B) =@= r(false, true, false, true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["Animal owl:disjointWith Plant", "cow rdf:type Animal"]]),
            ok(C, safe_add, [["cow rdf:type Plant"]], A),
            ok(C, check_consistency, [], Ok),
            ok(C, exist, [["cow rdf:type Plant"]], Kept),
            ok(C, revise, [["daisy rdf:type Plant"], _{method:"safe_add"}], B)
          )).
test(explain, true(r(Entailed, Asserted, Axioms) =@=
                   r(true, ["gorilla rdf:type Monkey"], ["Monkey rdfs:subClassOf Animal"]))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["gorilla rdf:type Monkey", "Monkey rdfs:subClassOf Animal"]]),
            ok(C, explain, [["gorilla rdf:type Animal"]], [E]),
            get_dict(entailed, E, Entailed),
            get_dict(asserted, E, Asserted),
            get_dict(axioms, E, Axioms)
          )).
test(categorization, true(r(S, D) =@= r(true, true))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["Dog rdfs:subClassOf Animal", "Cat rdfs:subClassOf Animal",
                            "rex rdf:type Dog", "tom rdf:type Cat",
                            "rex hasColor brown", "tom hasColor brown"]]),
            ok(C, similarities, ["rex", "tom"], Sims),
            test_bool(memberchk(["hasColor", "brown"], Sims), S),
            ok(C, discriminate, [["rex", "tom"]], Disc),
            get_dict(best, Disc, Best),
            test_bool(memberchk("rdf:type", Best), D)
          )).
test(oro_client_sees_kb_facts, true(V == ok("[\"alfred\"]"))) :-
    kb(C, ( ok(C, clear, []),
            ok(C, update, [["alfred rdf:type Human"]]) )),
    test_call(find, ["x", "[?x rdf:type Human]"], V).

:- end_tests(kbapi_reasoning).

                 /*******************************
                 *           LIFESPANS          *
                 *******************************/

%   The memory clock is set by the test (oro_memory's test clock): a
%   fact added with lifespan 0.5 s is there 0.4 s later and gone 0.5 s
%   later, at the default time base (one unit a second).

kb_t0(1700000000000).

kb_clock(Ms) :-
    oro_memory:set_test_clock(Ms).

kb_clocked :-
    kb_start,
    kb_t0(T0),
    kb_clock(T0).

kb_unclocked :-
    kb_clock(system),
    kb_stop.

:- begin_tests(kbapi_lifespan, [setup(kb_clocked), cleanup(kb_unclocked)]).

test(memory, true(L =@= [true, true, false, true])) :-
    kb(C, ( ok(C, update, [["john rdf:type Human"]]),
            kb_t0(T0),
            T1 is T0 + 1200,
            kb_clock(T1),
            oro_memory_sync,
            ok(C, exist, [["john rdf:type Human"]], A),
            ok(C, remove, [["john rdf:type Human"]]),
            ok(C, add, [["john rdf:type Human"], [], 0.5]),
            T2 is T1 + 400,
            kb_clock(T2),
            oro_memory_sync,
            ok(C, exist, [["john rdf:type Human"]], B),
            T3 is T1 + 500,
            kb_clock(T3),
            oro_memory_sync,
            ok(C, exist, [["john rdf:type Human"]], D),
            kb_call(C, add, [["jim rdf:type Human"]], _{lifespan:0}, ok),
            T4 is T3 + 100000,
            kb_clock(T4),
            oro_memory_sync,
            ok(C, exist, [["jim rdf:type Human"]], E),
            L = [A, B, D, E]
          )).
test(revise_lifespan_in_models, true(r(A, B) =@= r(true, false))) :-
    kb(C, ( kb_t0(T0),
            T1 is T0 + 200000,
            kb_clock(T1),
            ok(C, revise, [["tim isIn kitchen"],
                           _{method:"update", models:["model1"], lifespan:2}]),
            T2 is T1 + 1999,
            kb_clock(T2),
            oro_memory_sync,
            ok(C, exist, [["tim isIn kitchen"], ["model1"]], A),
            T3 is T1 + 2000,
            kb_clock(T3),
            oro_memory_sync,
            ok(C, exist, [["tim isIn kitchen"], ["model1"]], B) )).
test(forgetting_fires_event, true(E =@= [_{o:"alfred"}])) :-
    kb(C, ( ok(C, clear, []),
            ok(C, subscribe, [["?o isIn room"]], Id),
            kb_t0(T0),
            T1 is T0 + 300000,
            kb_clock(T1),
            kb_call(C, add, [["alfred isIn room"]], _{lifespan:1}, ok),
            event(C, Id, _),
            T2 is T1 + 1000,
            kb_clock(T2),
            oro_memory_sync,
            kb_events_sync,                 % forgetting evaluated
            ok(C, add, [["alfred isIn room"]]),
            event(C, Id, E) )).
test(bad_lifespan, true(r(A, B) =@= r(true, true))) :-
    kb(C, ( test_bool(is_error(C, add, [["a b c"], null, -1]), A),
            test_bool(is_error(C, add, [["a b c"], null, "soon"]), B) )).

:- end_tests(kbapi_lifespan).

                 /*******************************
                 *          LOAD, SAVE          *
                 *******************************/

kb_files_start(Dir) :-
    tmp_file(kbapi, Dir),
    make_directory(Dir),
    test_server_start([commonsense(false), kb_port(0), save_dir(Dir)]).

kb_files_stop(Dir) :-
    kb_stop,
    delete_directory_and_contents(Dir).

:- begin_tests(kbapi_files).

test(save_and_load, [ setup(kb_files_start(Dir)),
                      cleanup(kb_files_stop(Dir)),
                      true(r(Saved, Here, There) =@= r(true, true, false))
                    ]) :-
    directory_file_path(Dir, 'world.ttl', World),
    setup_call_cleanup(open(World, write, Out),
                       format(Out, "@prefix : <http://kb.openrobots.org#> .~n\c
                                    :cup1 :isOn :table1 .~n", []),
                       close(Out)),
    kb(C, ( ok(C, add, [["fork1 isOn table1"]]),
            kb_call(C, save, [], _{basename:"snap"}, ok),
            directory_file_path(Dir, 'snap-myself.rdf', Snap),
            test_bool(exists_file(Snap), Saved),
            ok(C, load, [World, ["loaded"]]),
            ok(C, exist, [["cup1 isOn table1"], ["loaded"]], Here),
            ok(C, exist, [["cup1 isOn table1"]], There)
          )).
test(load_missing_file, [ setup(kb_files_start(Dir)),
                          cleanup(kb_files_stop(Dir)),
                          true(E == true)
                        ]) :-
    directory_file_path(Dir, 'none.ttl', None),
    kb(C, test_bool(is_error(C, load, [None]), E)).

:- end_tests(kbapi_files).
