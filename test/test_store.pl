:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for the store (library(oro/oro_store)): ontologies loaded by
    oro_init/1 in N-Triples (test/fixtures/store_kitchen.nt) and RDF/XML
    (test/fixtures/store_dining.rdf); the ontology layer is read-only,
    whatever a model removes, updates or re-adds; masks are per model,
    so removing an ontology triple from `myself` leaves it in another
    agent's model; graph names come from the naming predicates
    (oro_graph/3 for a model's layers, oro_shared_graph/2 for the
    ontology layer) and from nowhere else.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_store.pl
*/

:- use_module(library(oro/oro_store)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).

%   Fresh stores: one fixture, both, or both with a second model
%   `toto` over the same ontology layer.

st_kitchen :-
    test_fixture('store_kitchen.nt', File),
    oro_init([commonsense(false), ontologies([File])]).

st_dining :-
    test_fixture('store_dining.rdf', File),
    oro_init([commonsense(false), ontologies([File])]).

st_both :-
    test_fixture('store_kitchen.nt', NT),
    test_fixture('store_dining.rdf', RDF),
    oro_init([commonsense(false), ontologies([NT, RDF])]).

st_two_models :-
    st_both,
    oro_create_model(toto).

%   st_iri(+Local, -IRI): Local in the default namespace.

st_iri(Local, IRI) :-
    rdf_global_id(oro:Local, IRI).

%   st_iris(+Format, +N, -IRIs): the IRIs of the local names Format
%   makes of 1 to N.

st_iris(Format, N, IRIs) :-
    findall(IRI,
            ( between(1, N, I),
              format(atom(Local), Format, [I]),
              st_iri(Local, IRI)
            ),
            IRIs).

%   st_triple(+Statement, -Triple): the rdf/3 term of a statement text.

st_triple(Statement, Triple) :-
    oro_statements([Statement], [Triple], _).

%   st_ontology(-Graphs): the graphs of the ontology layer, in load
%   order; st_ontology_triples(-Triples): their triples, sorted.

st_ontology(Graphs) :-
    findall(G, oro_ontology_graph(G), Graphs).

st_ontology_triples(Triples) :-
    st_ontology(Graphs),
    findall(rdf(S, P, O),
            ( member(G, Graphs),
              rdf(S, P, O, G)
            ),
            Triples0),
    msort(Triples0, Triples).

%   st_graph_triples(+Model, +Layer, -Triples): the triples of the
%   graph of Layer of Model, sorted.

st_graph_triples(Model, Layer, Triples) :-
    oro_graph(Model, Layer, Graph),
    findall(rdf(S, P, O), rdf(S, P, O, Graph), Triples0),
    msort(Triples0, Triples).

%   st_holds(+Model, +Statement, -Bool)

st_holds(Model, Statement, Bool) :-
    test_bool(oro_check(Model, [Statement]), Bool).

%   st_layers(-Layers): the layers of a model.

st_layers([profile(longterm), profile(shortterm), profile(episodic), mask]).


                 /*******************************
                 *           N-TRIPLES          *
                 *******************************/

:- begin_tests(store_ntriples).

test(facts, [ setup(st_kitchen),
              true(Holds == [true, true, true])
            ]) :-
    maplist(st_holds(myself), [ "mug1 rdf:type Mug",
                                "mug1 isOn shelf1",
                                "mug1 capacity 250"
                              ],
            Holds).
test(inference_from_schema, [ setup(st_kitchen),
                              true(Xs == [mug1])
                            ]) :-
    test_find(myself, x, ["?x rdf:type Container"], Xs).
test(typed_literal, [ setup(st_kitchen),
                      true(Os == [L])
                    ]) :-
    st_iri(mug1, Mug),
    st_iri(capacity, Capacity),
    findall(O, oro_asserted(myself, Mug, Capacity, O), Os),
    test_literal(xsd:int, '250', L).
test(escaped_label, [ setup(st_kitchen),
                      true(Label == 'tasse "caf\u00e9"')
                    ]) :-
    st_iri(mug1, Mug),
    oro_label(myself, Mug, fr, Label).
test(one_graph, [ setup(st_kitchen),
                  true(Graphs-Count == [Graph]-9)
                ]) :-
    st_ontology(Graphs),
    oro_shared_graph(ontology(1), Graph),
    rdf_statistics(triples_by_graph(Graph, Count)).
test(nothing_asserted_but_robot_type, [ setup(st_kitchen),
                                        true(Count == 1)
                                      ]) :-
    oro_asserted_count(myself, Count).

:- end_tests(store_ntriples).


                 /*******************************
                 *            RDF/XML           *
                 *******************************/

:- begin_tests(store_rdfxml).

test(facts, [ setup(st_dining),
              true(Holds == [true, true])
            ]) :-
    maplist(st_holds(myself), [ "plate1 rdf:type Plate",
                                "plate1 isOn table1"
                              ],
            Holds).
test(inference_from_schema, [ setup(st_dining),
                              true(Xs == [plate1])
                            ]) :-
    test_find(myself, x, ["?x rdf:type Container"], Xs).
test(typed_literal, [ setup(st_dining),
                      true(Os == [L])
                    ]) :-
    st_iri(plate1, Plate),
    st_iri(weight, Weight),
    findall(O, oro_asserted(myself, Plate, Weight, O), Os),
    test_literal(xsd:double, '0.4', L).
test(label, [ setup(st_dining),
              true(Label == 'dinner plate')
            ]) :-
    st_iri(plate1, Plate),
    oro_label(myself, Plate, Label).
test(one_graph, [ setup(st_dining),
                  true(Graphs-Count == [Graph]-7)
                ]) :-
    st_ontology(Graphs),
    oro_shared_graph(ontology(1), Graph),
    rdf_statistics(triples_by_graph(Graph, Count)).

:- end_tests(store_rdfxml).


                 /*******************************
                 *         SEVERAL FILES        *
                 *******************************/

:- begin_tests(store_several_files).

test(graphs_in_load_order, [ setup(st_both),
                             true(Graphs == [G1, G2])
                           ]) :-
    st_ontology(Graphs),
    oro_shared_graph(ontology(1), G1),
    oro_shared_graph(ontology(2), G2).
test(each_file_its_graph, [ setup(st_both),
                            true(Where == [1-mug1, 2-plate1])
                          ]) :-
    findall(N-Name,
            ( member(N, [1, 2]),
              oro_shared_graph(ontology(N), Graph),
              rdf(Subject, rdf:type, _, Graph),
              st_iri(Name, Subject),
              sub_atom(Name, _, 1, 0, '1')
            ),
            Where).
test(schema_across_files, [ setup(st_both),
                            true(Xs == [mug1, plate1])
                          ]) :-
    test_find(myself, x, ["?x rdf:type Container"], Xs).
test(unknown_extension,
     [ error(domain_error(ontology_file, _)),
       cleanup(st_kitchen)
     ]) :-
    test_fixture('plugins/good_plugin.pl', File),
    oro_init([commonsense(false), ontologies([File])]).

:- end_tests(store_several_files).


                 /*******************************
                 *     READ-ONLY ONTOLOGY LAYER *
                 *******************************/

:- begin_tests(store_read_only).

test(changes_leave_the_layer, [ setup(st_both),
                                true(After == Before)
                              ]) :-
    st_ontology_triples(Before),
    oro_add(myself, ["cup1 rdf:type Mug", "mug1 isOn table1"]),
    oro_remove(myself, ["mug1 isOn shelf1", "Plate rdfs:subClassOf Container"]),
    oro_clear(myself, ["plate1 ?p ?o"]),
    oro_update(myself, ["mug1 capacity 300"]),
    oro_add(myself, ["mug1 capacity 400"], shortterm),
    st_ontology_triples(After).
test(remove_masks, [ setup(st_kitchen),
                     true(Result == [false, [T], true])
                   ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    st_holds(myself, "mug1 isOn shelf1", Holds),
    st_triple("mug1 isOn shelf1", T),
    st_graph_triples(myself, mask, Masked),
    oro_shared_graph(ontology(1), Graph),
    T = rdf(S, P, O),
    test_bool(rdf(S, P, O, Graph), Kept),
    Result = [Holds, Masked, Kept].
test(removed_schema_stops_inference, [ setup(st_kitchen),
                                       true(Xs == [])
                                     ]) :-
    oro_remove(myself, ["Mug rdfs:subClassOf Container"]),
    test_find(myself, x, ["?x rdf:type Container"], Xs).
test(add_back_unmasks, [ setup(st_kitchen),
                         true(Result == [true, [], []])
                       ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    oro_add(myself, ["mug1 isOn shelf1"]),
    st_holds(myself, "mug1 isOn shelf1", Holds),
    st_graph_triples(myself, mask, Masked),
    st_triple("mug1 isOn shelf1", T),
    st_graph_triples(myself, profile(longterm), Long),
    include(==(T), Long, Copies),
    Result = [Holds, Masked, Copies].
test(known_fact_not_copied, [ setup(st_kitchen),
                              true(Count == 1)
                            ]) :-
    oro_add(myself, ["mug1 isOn shelf1", "mug1 rdf:type Mug"]),
    oro_asserted_count(myself, Count).
test(update_masks_ontology_value, [ setup(st_kitchen),
                                    true(Values-Kept == ['300']-true)
                                  ]) :-
    oro_update(myself, ["mug1 capacity 300"]),
    test_find(myself, c, ["mug1 capacity ?c"], Values),
    st_triple("mug1 capacity 250", rdf(S, P, O)),
    oro_shared_graph(ontology(1), Graph),
    test_bool(rdf(S, P, O, Graph), Kept).
test(clear_masks_matches, [ setup(st_kitchen),
                            true(Result == [[], 9])
                          ]) :-
    oro_clear(myself, ["mug1 ?p ?o"]),
    st_iri(mug1, Mug),
    findall(P-O, oro_asserted(myself, Mug, P, O), Left),
    oro_shared_graph(ontology(1), Graph),
    rdf_statistics(triples_by_graph(Graph, Count)),
    Result = [Left, Count].
test(reset_lifts_masks, [ setup(st_kitchen),
                          true(Result == [true, []])
                        ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    oro_reset,
    st_holds(myself, "mug1 isOn shelf1", Holds),
    st_graph_triples(myself, mask, Masked),
    Result = [Holds, Masked].

:- end_tests(store_read_only).


                 /*******************************
                 *        PER-MODEL MASKS       *
                 *******************************/

:- begin_tests(store_masks).

test(remove_in_myself_kept_in_toto, [ setup(st_two_models),
                                      true(Result == [false, true, [], [T]])
                                    ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    st_holds(myself, "mug1 isOn shelf1", Mine),
    st_holds(toto, "mug1 isOn shelf1", Toto),
    st_triple("mug1 isOn shelf1", T),
    st_graph_triples(toto, mask, TotoMask),
    st_graph_triples(myself, mask, MyMask),
    Result = [Mine, Toto, TotoMask, MyMask].
test(remove_in_toto_kept_in_myself, [ setup(st_two_models),
                                      true(Result == [true, false])
                                    ]) :-
    oro_remove(toto, ["plate1 isOn table1"]),
    st_holds(myself, "plate1 isOn table1", Mine),
    st_holds(toto, "plate1 isOn table1", Toto),
    Result = [Mine, Toto].
test(asserted_per_model, [ setup(st_two_models),
                           true(Result == [false, true])
                         ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    st_triple("mug1 isOn shelf1", rdf(S, P, O)),
    test_bool(oro_asserted(myself, S, P, O), Mine),
    test_bool(oro_asserted(toto, S, P, O), Toto),
    Result = [Mine, Toto].
test(inference_per_model, [ setup(st_two_models),
                            true(Result == [[plate1], [mug1, plate1]])
                          ]) :-
    oro_remove(myself, ["mug1 rdf:type Mug"]),
    test_find(myself, x, ["?x rdf:type Container"], Mine),
    test_find(toto, x, ["?x rdf:type Container"], Toto),
    Result = [Mine, Toto].
test(schema_removal_per_model, [ setup(st_two_models),
                                 true(Result == [[mug1], [mug1, plate1]])
                               ]) :-
    oro_remove(myself, ["Plate rdfs:subClassOf Container"]),
    test_find(myself, x, ["?x rdf:type Container"], Mine),
    test_find(toto, x, ["?x rdf:type Container"], Toto),
    Result = [Mine, Toto].
test(update_per_model, [ setup(st_two_models),
                         true(Result == [['300'], ['250']])
                       ]) :-
    oro_update(myself, ["mug1 capacity 300"]),
    test_find(myself, c, ["mug1 capacity ?c"], Mine),
    test_find(toto, c, ["mug1 capacity ?c"], Toto),
    Result = [Mine, Toto].
test(removed_in_both, [ setup(st_two_models),
                        true(Result == [false, false, true])
                      ]) :-
    oro_remove(myself, ["mug1 isOn shelf1"]),
    oro_remove(toto, ["mug1 isOn shelf1"]),
    st_holds(myself, "mug1 isOn shelf1", Mine),
    st_holds(toto, "mug1 isOn shelf1", Toto),
    st_triple("mug1 isOn shelf1", rdf(S, P, O)),
    oro_shared_graph(ontology(1), Graph),
    test_bool(rdf(S, P, O, Graph), Kept),
    Result = [Mine, Toto, Kept].
test(added_facts_stay_in_their_model, [ setup(st_two_models),
                                        true(Result == [false, true])
                                      ]) :-
    oro_add(toto, ["cup1 rdf:type Mug"]),
    st_holds(myself, "cup1 rdf:type Container", Mine),
    st_holds(toto, "cup1 rdf:type Container", Toto),
    Result = [Mine, Toto].

:- end_tests(store_masks).


                 /*******************************
                 *          GRAPH NAMES         *
                 *******************************/

:- begin_tests(store_graph_names).

test(one_graph_per_model_and_layer, [ setup(st_two_models),
                                      true(N == 8)
                                    ]) :-
    st_layers(Layers),
    findall(G,
            ( member(M, [myself, toto]),
              member(L, Layers),
              oro_graph(M, L, G)
            ),
            Graphs0),
    sort(Graphs0, Graphs),
    length(Graphs, N).
test(graph_det, [ setup(st_two_models),
                  forall(( member(M, [myself, toto]),
                           st_layers(Layers),
                           member(L, Layers)
                         )),
                  true(Det == true)
                ]) :-
    call_cleanup(oro_graph(M, L, _), Det = true).
test(layer_of_graph, [ setup(st_two_models),
                       forall(( member(M, [myself, toto]),
                                st_layers(Layers),
                                member(L, Layers)
                              )),
                       true(M2-L2 == M-L)
                     ]) :-
    oro_graph(M, L, G),
    oro_graph_layer(G, M2, L2).
test(ontology_graphs_not_model_graphs, [ setup(st_two_models),
                                         true(Owners == [])
                                       ]) :-
    st_ontology(Graphs),
    findall(M-L,
            ( member(G, Graphs),
              oro_graph_layer(G, M, L)
            ),
            Owners).
test(asserted_in_profile_graph, [ setup(st_two_models),
                                  true(Where == [myself-longterm, toto-shortterm])
                                ]) :-
    oro_add(myself, ["cup1 isOn shelf1"]),
    oro_add(toto, ["cup1 isOn shelf1"], shortterm),
    st_triple("cup1 isOn shelf1", T),
    findall(M-Profile,
            ( oro_model(M),
              member(Profile, [longterm, shortterm, episodic]),
              oro_graph(M, profile(Profile), G),
              T = rdf(S, P, O),
              rdf(S, P, O, G)
            ),
            Where0),
    sort(Where0, Where).
test(every_graph_named, [ setup(st_two_models),
                          true(Unnamed == [])
                        ]) :-
    oro_add(myself, ["cup1 isOn shelf1"]),
    oro_add(toto, ["cup2 isOn shelf1"], episodic),
    oro_remove(toto, ["mug1 isOn shelf1"]),
    oro_update(myself, ["mug1 capacity 300"]),
    findall(G,
            ( rdf_graph(G),
              \+ oro_graph_layer(G, _, _),
              \+ oro_ontology_graph(G)
            ),
            Unnamed).
test(bad_ontology_index, error(type_error(positive_integer, 0))) :-
    oro_shared_graph(ontology(0), _).

:- end_tests(store_graph_names).


                 /*******************************
                 *            GC PIN            *
                 *******************************/

/*  rdf_db 9.0.4's garbage collector, when a pass starts with no
    snapshot alive, reclaims the triples deleted during the pass, even
    those a snapshot taken meanwhile must still see: rdf/3 then misses
    them in that snapshot.  The store keeps a snapshot alive at all
    times (the GC pin) so that it cannot happen.  The race test writes
    and deletes triples as the event watchers see them (a snapshot after
    each write, read by another thread), while a third thread runs the
    collector without pause.  Without the pin most runs miss triples.
*/

:- begin_tests(store_gc_pin, [setup(st_kitchen), cleanup(st_kitchen)]).

test(snapshot_keeps_its_triples_while_gc_runs, Missed == 0) :-
    st_gc_race(5000, Missed).
test(removal_reclaimed_after_next_write, true(Kept1-Kept2 == kept-none)) :-
    st_iri(gc_cup, S),
    st_put(S, gc_table),
    st_take(S, gc_table),
    st_kept_garbage(Kept0),
    functor(Kept0, Kept1, _),
    st_put(S, gc_shelf),
    st_kept_garbage(Kept2).
test(removals_in_a_row_reclaimed, true(Kept == none)) :-
    st_iris('gc_row_~d', 3, Subjects),
    forall(member(S, Subjects), st_put(S, gc_table)),
    forall(member(S, Subjects), st_take(S, gc_table)),
    st_kept_garbage(kept(Stored, Live)),
    assertion(Stored - Live =:= 1),     % the last removal's triple only
    st_iri(gc_lamp, S2),
    st_put(S2, gc_table),
    st_kept_garbage(Kept).
test(pin_renewed_by_each_write, true(Pin \== Pin0)) :-
    st_iri(gc_mug, S),
    st_put(S, gc_table),
    thread_peek_message(oro_gc_pin, gc_pin(Pin0)),
    st_put(S, gc_shelf),
    thread_peek_message(oro_gc_pin, gc_pin(Pin)).
test(unmask_reclaimed_after_next_write, true(Kept == none)) :-
    st_triple("Mug rdfs:subClassOf Container", Triple),
    oro_store_write(test, oro_store_retract(myself, [Triple])),
    oro_store_write(test, oro_store_assert(myself, [Triple], longterm)),
    st_iri(gc_bowl, S),
    st_put(S, gc_table),
    st_kept_garbage(Kept).
test(pin_after_rebuild, true(Kept == none)) :-
    assertion(oro_store_rebuild),
    st_kept_garbage(Kept).
test(erased_pin_dropped, true(Kept == none)) :-
    rdf_snapshot(Gone),                 % as rdf_reset_db/0 would leave it
    rdf_delete_snapshot(Gone),
    with_mutex(oro_write, thread_send_message(oro_gc_pin, gc_pin(Gone))),
    st_iri(gc_plate, S),
    st_put(S, gc_table),
    st_take(S, gc_table),
    st_put(S, gc_shelf),
    st_kept_garbage(Kept).

%   st_put(+S, +Place), st_take(+S, +Place): one write asserting, or
%   retracting, `S isOn Place` in the robot's model.

st_put(S, Place) :-
    st_is_on(S, Place, Triple),
    oro_store_write(test, oro_store_assert(myself, [Triple], longterm)).

st_take(S, Place) :-
    st_is_on(S, Place, Triple),
    oro_store_write(test, oro_store_retract(myself, [Triple])).

st_is_on(S, Place, rdf(S, P, O)) :-
    st_iri(isOn, P),
    st_iri(Place, O).

%   st_kept_garbage(-Kept): `none` if a snapshot is alive (the pin) and
%   yet, once rdf_db's GC has run, no deleted triple is kept: the pin is
%   newer than the last write that deleted triples.  rdf_gc_info_/1 is
%   rdf_db's own account: its first argument counts the triples not
%   reclaimed, deleted or not; its fifth is the oldest generation a
%   snapshot or query may read, GEN_MAX (2^63-1) when there is none.

st_kept_garbage(Kept) :-
    oro_events_sync,                    % the watcher lets go of its snapshots
    rdf_gc,
    rdf_db:rdf_gc_info_(Info),
    arg(1, Info, Stored),
    arg(5, Info, KeepGen),
    rdf_statistics(triples(Live)),
    (   KeepGen =:= 0x7fffffffffffffff
    ->  Kept = no_pin
    ;   Stored =:= Live
    ->  Kept = none
    ;   Kept = kept(Stored, Live)
    ).

%   st_gc_race(+Rounds, -Missed): Rounds times, add six triples in one
%   write, take a snapshot, delete them in a second write; another
%   thread checks each snapshot for the six triples and sends back
%   gc_missed(Missed), the number of snapshots missing one, while a
%   third runs rdf_gc/0 until the writer is done (at most 100,000
%   passes).

st_gc_race(Rounds, Missed) :-
    message_queue_create(Queue, [max_size(64)]),
    thread_self(Me),
    thread_create(st_gc_checker(Queue, Me, 0), Checker, []),
    thread_create(st_gc_hammer(100000), Hammer, []),
    call_cleanup(forall(between(1, Rounds, Round),
                        st_gc_round(Queue, Round)),
                 ( thread_send_message(Queue, done),
                   thread_send_message(Hammer, done),
                   thread_join(Checker, CheckerStatus),
                   thread_join(Hammer, _),
                   message_queue_destroy(Queue)
                 )),
    assertion(CheckerStatus == true),
    thread_get_message(gc_missed(Missed)).

st_gc_round(Queue, Round) :-
    Sub is Round mod 4,
    format(atom(Local), 'gc_obj_~d', [Sub]),
    st_iri(Local, S),
    st_iri(gc_place, O),
    st_iris('gc_rel_~d', 6, Predicates),
    findall(rdf(S, P, O), member(P, Predicates), Triples),
    oro_store_write(test, oro_store_assert(myself, Triples, longterm)),
    rdf_snapshot(Snapshot),
    thread_send_message(Queue, check(Snapshot, Triples)),
    oro_store_write(test, oro_store_retract(myself, Triples)).

st_gc_checker(Queue, Caller, Missed0) :-
    thread_get_message(Queue, Message),
    (   Message = check(Snapshot, Triples)
    ->  rdf_transaction(st_gc_miss(Triples, Miss), st_gc,
                        [snapshot(Snapshot)]),
        rdf_delete_snapshot(Snapshot),
        Missed1 is Missed0 + Miss,
        st_gc_checker(Queue, Caller, Missed1)
    ;   thread_send_message(Caller, gc_missed(Missed0))
    ).

st_gc_miss(Triples, Miss) :-
    (   member(rdf(S, P, O), Triples),
        \+ rdf(S, P, O)
    ->  Miss = 1
    ;   Miss = 0
    ).

%   st_gc_hammer(+Passes): run rdf_gc/0 until a `done` message comes,
%   at most Passes times; after the last pass, wait for `done` (the
%   message is sent to this thread, which must still exist).

st_gc_hammer(0) :-
    !,
    thread_get_message(done).
st_gc_hammer(_) :-
    thread_peek_message(done),
    !.
st_gc_hammer(Passes) :-
    rdf_gc,
    Passes1 is Passes - 1,
    st_gc_hammer(Passes1).

:- end_tests(store_gc_pin).

%   Writes that only add leave no clause behind for SWI-Prolog's clause
%   garbage collector (see oro_store, "Writes leave no clause behind"),
%   here with the bundled ontology, whose agents module keeps a watcher
%   (so the events monitor notes every write).

:- begin_tests(store_clause_churn, [setup(oro_init([])), cleanup(oro_init([]))]).

test(adds_retract_no_clause, true(Reclaimed < 20)) :-
    test_churn_adds(warm, _),
    test_churn_adds(probe, Reclaimed).
test(removals_retract_no_clause, true(Reclaimed < 20)) :-
    test_churn_adds(removed, _),
    test_reclaimed(
        forall(( between(1, 20, I),
                 between(1, 9, J)               % place_10 stays: no name goes
               ),
               ( format(string(S), "churn_removed_~d isOn place_~d", [I, J]),
                 oro_remove(myself, [S])
               )),
        Reclaimed).

:- end_tests(store_clause_churn).

:- begin_tests(store_ontology_base).

%   An ontology's relative IRIs resolve against the file's URL (the name
%   of its graph for SPARQL), not against the rdf_db graph name.

test(relative_iris_resolve_against_file, [true(Found == [true, true])]) :-
    test_fixture('relative_iris.ttl', File),
    oro_init([commonsense(false), ontologies([File])]),
    uri_file_name(URL, File),
    atom_concat(URL, '#Gadget', Gadget),
    atom_concat(URL, '#Thing', Thing),
    test_bool(rdf(Gadget, rdfs:subClassOf, Thing), F1),
    test_bool(rdf(URL, rdfs:label, _), F2),
    Found = [F1, F2].

:- end_tests(store_ontology_base).
