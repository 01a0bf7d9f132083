:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/oro_memory),
              [ oro_memory_profile/2,
                oro_memory_lifetime/2,
                oro_memory_sync/0
              ]).
:- use_module(library(oro/oro_store), [oro_store_write/2]).

/*  Tests for memory profiles (ORO-SPEC §9, add(Set, String) of §6.1,
    the vectors of §13.12), through the Prolog API (oro_add/3,
    oro_memory_deadlines/2, oro_memory_sync/0) and over the socket.

    What is checked: SHORTTERM lives 10 time units, EPISODIC 300,
    LONGTERM and DEFAULT forever; names in any case, unknown ones
    meaning DEFAULT; a deadline is never earlier than now + lifetime
    and a fact is never forgotten before it; re-adding a long-term fact
    as SHORTTERM does not make it forgettable; re-adding a short-term
    fact restarts its lifetime; a fact added both SHORTTERM and
    EPISODIC stays until the later deadline; forgetting updates the
    inferences and fires events (NEW_INSTANCE and FACT_CHECKING
    ON_FALSE); no reification triples (`rs_...`) are ever visible;
    with the memory clock set by the test (no wall-clock dependence): a
    fact goes exactly at its deadline, batches with later deadlines
    stay, and a fact refreshed after the scheduler popped its old
    deadline (or while the scheduler waits for the store's write lock)
    is not forgotten by it.

    A small time base (50 ms; 5 ms to see EPISODIC facts go) keeps the
    tests short.  Waits are on conditions (polling every 10 ms, 5 s
    at most), never fixed sleeps.  Tests marked blocked/1 show bugs of
    the implementation: the reason says which.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_memory.pl
*/

:- dynamic
    agm_mem_started_time_base/1.        % Milliseconds


                 /*******************************
                 *        PROLOG HELPERS        *
                 *******************************/

%   agm_mem_fresh(+TimeBase): the common-sense ontology, robot id
%   ROBOT, the time base in milliseconds.

agm_mem_fresh(TimeBase) :-
    oro_init([robot_id('ROBOT'), time_base(TimeBase)]).

agm_mem_fresh :-
    agm_mem_fresh(50).

agm_mem_now(Ms) :-
    get_time(Now),
    Ms is Now * 1000.

agm_mem_holds(Model, Statement) :-
    oro_check(Model, [Statement]).

agm_mem_gone(Model, Statement) :-
    \+ oro_check(Model, [Statement]).

%   agm_mem_deadlines(+Model, -Deadlines): Deadline-Statement-Profile
%   with contracted statement text, earliest first.

agm_mem_deadlines(Model, Deadlines) :-
    oro_memory_deadlines(Model, Deadlines0),
    maplist(agm_mem_deadline, Deadlines0, Deadlines).

agm_mem_deadline(D-rdf(S, P, O)-Profile, D-Text-Profile) :-
    maplist(oro_term_text, [S, P, O], Parts),
    atomic_list_concat(Parts, ' ', Atom),
    atom_string(Atom, Text).

%   agm_mem_deadline_of(+Model, +Statement, +Profile, -Deadline) is
%   semidet.

agm_mem_deadline_of(Model, Statement, Profile, Deadline) :-
    agm_mem_deadlines(Model, Deadlines),
    memberchk(Deadline-Statement-Profile, Deadlines).

%   agm_mem_statements_with_deadline(+Model, -Statements): sorted.

agm_mem_statements_with_deadline(Model, Statements) :-
    agm_mem_deadlines(Model, Deadlines),
    findall(S, member(_-S-_, Deadlines), Statements0),
    sort(Statements0, Statements).

%   agm_mem_forgotten(:Gone, +Deadline, -Outcome): wait (5 s at most)
%   until Gone holds.  Outcome is `after_deadline` if it did not hold
%   before Deadline (ms since the epoch), early(Ms) if it held Ms
%   before it, or `never`.

:- meta_predicate agm_mem_forgotten(0, +, -).

agm_mem_forgotten(Gone, Deadline, Outcome) :-
    (   test_wait_until(Gone, 5)
    ->  agm_mem_now(Seen),
        (   Seen >= Deadline
        ->  Outcome = after_deadline
        ;   Early is Deadline - Seen,
            Outcome = early(Early)
        )
    ;   Outcome = never
    ).

%   agm_mem_wait_after(+Deadline): wait (5 s at most) until the clock
%   has passed Deadline (ms since the epoch).

agm_mem_wait_after(Deadline) :-
    test_wait_until(( agm_mem_now(Now), Now > Deadline ), 5).

%   agm_mem_short_marker(+Model, -Outcome): add `marker is set` as
%   SHORTTERM and wait until it is forgotten: every short-term fact
%   added before it is then due too.

agm_mem_short_marker(Model, Outcome) :-
    oro_add(Model, ["marker is set"], shortterm),
    agm_mem_deadline_of(Model, "marker is set", shortterm, Deadline),
    agm_mem_forgotten(agm_mem_gone(Model, "marker is set"), Deadline,
                      Outcome).

%   agm_mem_event_to(+Queue, +Id, +Content): an oro_subscribe/7 callback
%   noting when the event came.

agm_mem_event_to(Queue, Id, Content) :-
    agm_mem_now(Now),
    thread_send_message(Queue, event(Id, Content, Now)).

%   agm_mem_event_when(+Model, +Type, +Trigger, +Var, +Patterns,
%   :Goal, -Names, -Outcome): subscribe, run Goal (which
%   adds what will be forgotten), and wait (5 s at most) for the first
%   event.  Names is its contracted content, Outcome as for
%   agm_mem_forgotten/3 for the event's arrival against the deadline of
%   the first short-term fact of Model.

:- meta_predicate agm_mem_event_when(+, +, +, +, +, 0, -, -).

agm_mem_event_when(Model, Type, Trigger, Var, Patterns, Goal, Names,
                   Outcome) :-
    message_queue_create(Queue),
    setup_call_cleanup(
        oro_subscribe(Model, Type, Trigger, Var, Patterns,
                      agm_mem_event_to(Queue), Id),
        ( once(Goal),
          oro_memory_deadlines(Model, [Deadline-_-_|_]),
          (   thread_get_message(Queue, event(Id, Content, When),
                                 [timeout(5)])
          ->  maplist(oro_iri_name, Content, Names),
              (   When >= Deadline
              ->  Outcome = after_deadline
              ;   Early is Deadline - When,
                  Outcome = early(Early)
              )
          ;   Names = timeout,
              Outcome = never
          )
        ),
        ( oro_unsubscribe(Id),
          message_queue_destroy(Queue)
        )).


                 /*******************************
                 *      PROFILES AND DEADLINES  *
                 *******************************/

:- begin_tests(agm_mem_profiles).

test(profile_names, true(Profiles == [ shortterm, shortterm, shortterm,
                                       episodic, episodic, longterm,
                                       longterm, longterm, longterm,
                                       longterm ])) :-
    maplist(oro_memory_profile,
            ['SHORTTERM', shortterm, "ShortTerm", 'EPISODIC', "episodic",
             'LONGTERM', 'DEFAULT', default, bogus, ''],
            Profiles).
test(lifetimes, [ setup(agm_mem_fresh(50)),
                  true(Ls == [500, 15000, none])
                ]) :-
    findall(L, ( member(P, [shortterm, episodic, longterm]),
                 (   oro_memory_lifetime(P, L0)
                 ->  L = L0
                 ;   L = none
                 )
               ), Ls).
test(default_time_base, [ setup(oro_init([])),
                          true(Ls == [10000, 300000])
                        ]) :-
    maplist(oro_memory_lifetime, [shortterm, episodic], Ls).
test(long_term_has_no_deadline, [ setup(agm_mem_fresh),
                                  true(Ds == [])
                                ]) :-
    oro_add(myself, ["a1 p o"]),
    oro_add(myself, ["a2 p o"], 'LONGTERM'),
    oro_add(myself, ["a3 p o"], 'DEFAULT'),
    oro_add(myself, ["a4 p o"], bogus),
    oro_memory_deadlines(myself, Ds).
test(short_term_deadline, [ setup(agm_mem_fresh),
                            true(r(Late, Holds, Before) == r(true, true, true))
                          ]) :-
    agm_mem_now(T0),
    oro_add(myself, ["superman rdf:type Animal"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "superman rdf:type Animal", shortterm, D),
    test_bool(D >= T0 + 500, Late),
    test_bool(agm_mem_holds(myself, "superman rdf:type Animal"), Holds),
    agm_mem_now(T1),
    test_bool(T1 < D, Before).
test(episodic_deadline, [ setup(agm_mem_fresh),
                          true(Late-Holds == true-true)
                        ]) :-
    agm_mem_now(T0),
    oro_add(myself, ["snail eats grass"], episodic),
    agm_mem_deadline_of(myself, "snail eats grass", episodic, D),
    test_bool(D >= T0 + 15000, Late),
    test_bool(agm_mem_holds(myself, "snail eats grass"), Holds).
test(any_case, [ setup(agm_mem_fresh),
                 true(Ss == ["a1 p o", "a2 p o", "a3 p o"])
               ]) :-
    oro_add(myself, ["a1 p o"], "shortterm"),
    oro_add(myself, ["a2 p o"], 'ShortTerm'),
    oro_add(myself, ["a3 p o"], "Episodic"),
    agm_mem_statements_with_deadline(myself, Ss).
test(short_and_episodic, [ setup(agm_mem_fresh),
                           true(Ps == [shortterm, episodic])
                         ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_add(myself, ["f p o"], 'EPISODIC'),
    agm_mem_deadlines(myself, Ds),
    findall(P, member(_-"f p o"-P, Ds), Ps).
test(long_term_then_short_term, [ setup(agm_mem_fresh),
                                  true(Ds == [])
                                ]) :-
    oro_add(myself, ["f p o"]),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_memory_deadlines(myself, Ds).
test(ontology_fact_as_short_term, [ setup(agm_mem_fresh),
                                    true(Ds == [])
                                  ]) :-
    oro_add(myself, ["Human rdfs:subClassOf EmbodiedAgent"], 'SHORTTERM'),
    oro_memory_deadlines(myself, Ds).
test(refresh_moves_deadline, [ setup(agm_mem_fresh),
                               true(N-Later == 1-true)
                             ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "f p o", shortterm, D1),
    agm_mem_now(T0),
    test_wait_until(( agm_mem_now(T), T > T0 + 20 ), 5),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadlines(myself, Ds),
    findall(D, member(D-"f p o"-_, Ds), [D2|Rest]),
    length([D2|Rest], N),
    test_bool(D2 > D1, Later).
test(no_reification, [ setup(agm_mem_fresh),
                       true(r(Statements, Rs, Infos) == r([], [], []))
                     ]) :-
    oro_add(myself, ["superman rdf:type Animal"], 'SHORTTERM'),
    oro_add(myself, ["snail eats grass"], 'EPISODIC'),
    oro_add(myself, ["snail eats grass"], 'SHORTTERM'),
    test_find(myself, x, ["?x rdf:type rdf:Statement"], Statements),
    findall(S, ( rdf(S, _, _),
                 atom(S),
                 sub_atom(S, _, _, _, '#rs_')
               ), Rs0),
    sort(Rs0, Rs),
    oro_name_iri(superman, Superman),
    oro_infos(myself, Superman, Triples),
    findall(T, ( member(T, Triples),
                 term_to_atom(T, A),
                 (   sub_atom(A, _, _, _, 'Statement')
                 ;   sub_atom(A, _, _, _, rs_)
                 )
               ), Infos).
test(agent_model, [ setup(agm_mem_fresh),
                    true(G-M == ["hen has teeth"]-[])
                  ]) :-
    oro_add(myself, ["gerard rdf:type Human"]),
    oro_add(gerard, ["hen has teeth"], 'SHORTTERM'),
    agm_mem_statements_with_deadline(gerard, G),
    agm_mem_statements_with_deadline(myself, M).
test(reset_forgets_deadlines, [ setup(agm_mem_fresh),
                                true(Ds == [])
                              ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_reset,
    oro_memory_deadlines(myself, Ds).
test(bad_batch_no_deadline, [ setup(agm_mem_fresh),
                              true(Ds == [])
                            ]) :-
    catch(oro_add(myself, ["f p o", "g p"], 'SHORTTERM'),
          error(syntax_error(_), _),
          true),
    oro_memory_deadlines(myself, Ds).

:- end_tests(agm_mem_profiles).


                 /*******************************
                 *          FORGETTING          *
                 *******************************/

:- begin_tests(agm_mem_forgetting).

%   A 20 ms time base: SHORTTERM facts live 200 ms.


test(short_term_forgotten, [ setup(agm_mem_fresh(20)),
                             true(Outcome == after_deadline)
                           ]) :-
    oro_add(myself, ["superman rdf:type Animal"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "superman rdf:type Animal", shortterm, D),
    agm_mem_forgotten(agm_mem_gone(myself, "superman rdf:type Animal"), D,
                      Outcome).
test(deadline_dropped_once_forgotten, [ setup(agm_mem_fresh(20)),
                                        true(Outcome-Ds == after_deadline-[])
                                      ]) :-
    agm_mem_short_marker(myself, Outcome),
    oro_memory_sync,
    oro_memory_deadlines(myself, Ds).
test(sync_forgets_what_is_due, [ setup(agm_mem_fresh(10)),
                                 true(Holds == false)
                               ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "f p o", shortterm, D),
    agm_mem_wait_after(D),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(long_term_stays, [ setup(agm_mem_fresh(20)),
                        true(Marker-Holds == after_deadline-true)
                      ]) :-
    oro_add(myself, ["f p o"]),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(unknown_profile_stays, [ setup(agm_mem_fresh(20)),
                              true(Marker-Holds == after_deadline-true)
                            ]) :-
    oro_add(myself, ["x y z"], bogus),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "x y z"), Holds).
test(short_term_then_long_term_stays,
     [ setup(agm_mem_fresh(20)),
       true(Marker-Holds == after_deadline-true)
     ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_add(myself, ["f p o"]),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(removed_then_long_term_stays, [ setup(agm_mem_fresh(20)),
                                     true(Marker-Holds == after_deadline-true)
                                   ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_remove(myself, ["f p o"]),
    oro_add(myself, ["f p o"]),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(removed_ontology_fact_short_term_forgotten,
     [ setup(agm_mem_fresh(20)),
       true(Holds-Outcome == true-after_deadline)
     ]) :-
    % Removed from the robot's model, the ontology's triple no longer
    % lives forever there: added back as SHORTTERM, it fades.
    oro_remove(myself, ["Human rdfs:subClassOf EmbodiedAgent"]),
    oro_add(myself, ["Human rdfs:subClassOf EmbodiedAgent"], 'SHORTTERM'),
    test_bool(agm_mem_holds(myself, "Human rdfs:subClassOf EmbodiedAgent"),
              Holds),
    agm_mem_deadline_of(myself, "Human rdfs:subClassOf EmbodiedAgent",
                        shortterm, D),
    agm_mem_forgotten(agm_mem_gone(myself,
                                   "Human rdfs:subClassOf EmbodiedAgent"),
                      D, Outcome).
test(removed_ontology_fact_short_then_long_term_stays,
     [ setup(agm_mem_fresh(20)),
       true(Marker-Holds == after_deadline-true)
     ]) :-
    oro_remove(myself, ["Human rdfs:subClassOf EmbodiedAgent"]),
    oro_add(myself, ["Human rdfs:subClassOf EmbodiedAgent"], 'SHORTTERM'),
    oro_add(myself, ["Human rdfs:subClassOf EmbodiedAgent"]),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "Human rdfs:subClassOf EmbodiedAgent"),
              Holds).
test(literal_spelled_otherwise_forgotten,
     [ setup(agm_mem_fresh(20)),
       true(Outcome-After == after_deadline-[cup1])
     ]) :-
    % rdf_db stores 0.50 as the 0.5 it already holds: the short-term
    % fact still gets its deadline, and goes.
    oro_add(myself, ["cup1 hasWeight 0.5"]),
    oro_add(myself, ["cup2 hasWeight 0.50"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "cup2 hasWeight 0.5", shortterm, D),
    agm_mem_forgotten(agm_mem_gone(myself, "cup2 hasWeight 0.5"), D, Outcome),
    test_find(myself, x, ["?x hasWeight ?w"], After).
test(refresh, [ setup(agm_mem_fresh(20)),
                true(Outcome == after_deadline)
              ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "f p o", shortterm, D1),
    Half is D1 - 100,
    agm_mem_wait_after(Half),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "f p o", shortterm, D2),
    agm_mem_forgotten(agm_mem_gone(myself, "f p o"), D2, Outcome).
test(short_and_episodic, [ setup(agm_mem_fresh(5)),
                           true(Marker-Holds-Outcome ==
                                after_deadline-true-after_deadline)
                         ]) :-
    % 5 ms time base: SHORTTERM lives 50 ms, EPISODIC 1.5 s.
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    oro_add(myself, ["f p o"], 'EPISODIC'),
    agm_mem_deadline_of(myself, "f p o", episodic, D),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "f p o"), Holds),
    agm_mem_forgotten(agm_mem_gone(myself, "f p o"), D, Outcome).
test(episodic_and_short, [ setup(agm_mem_fresh(5)),
                           true(Marker-Holds-Outcome ==
                                after_deadline-true-after_deadline)
                         ]) :-
    oro_add(myself, ["f p o"], 'EPISODIC'),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_deadline_of(myself, "f p o", episodic, D),
    agm_mem_short_marker(myself, Marker),
    test_bool(agm_mem_holds(myself, "f p o"), Holds),
    agm_mem_forgotten(agm_mem_gone(myself, "f p o"), D, Outcome).
test(inferences_updated, [ setup(agm_mem_fresh(20)),
                           true(Before-Outcome-After ==
                                [superman]-after_deadline-[])
                         ]) :-
    oro_add(myself, ["Hero rdfs:subClassOf Animal"]),
    oro_add(myself, ["superman rdf:type Hero"], 'SHORTTERM'),
    test_find(myself, x, ["?x rdf:type Animal"], Before),
    agm_mem_deadline_of(myself, "superman rdf:type Hero", shortterm, D),
    agm_mem_forgotten(agm_mem_gone(myself, "superman rdf:type Animal"), D,
                      Outcome),
    test_find(myself, x, ["?x rdf:type Animal"], After).
test(new_instance_on_false, [ setup(agm_mem_fresh(20)),
                              true(Names-Outcome == [superman]-after_deadline)
                            ]) :-
    agm_mem_event_when(myself, new_instance, on_false, a,
                       ["?a rdf:type Animal"],
                       oro_add(myself, ["superman rdf:type Animal"],
                               'SHORTTERM'),
                       Names, Outcome).
test(new_instance_on_false_inferred,
     [ setup(agm_mem_fresh(20)),
       true(Names-Outcome == [superman]-after_deadline)
     ]) :-
    oro_add(myself, ["Hero rdfs:subClassOf Animal"]),
    agm_mem_event_when(myself, new_instance, on_false, a,
                       ["?a rdf:type Animal"],
                       oro_add(myself, ["superman rdf:type Hero"],
                               'SHORTTERM'),
                       Names, Outcome).
test(fact_checking_on_false, [ setup(agm_mem_fresh(20)),
                               true(Names-Outcome == []-after_deadline)
                             ]) :-
    agm_mem_event_when(myself, fact_checking, on_false, '',
                       ["superman rdf:type Animal"],
                       oro_add(myself, ["superman rdf:type Animal"],
                               'SHORTTERM'),
                       Names, Outcome).
test(agent_model, [ setup(agm_mem_fresh(20)),
                    true(Outcome-Robot == after_deadline-true)
                  ]) :-
    oro_add(myself, ["gerard rdf:type Human", "hen has teeth"]),
    oro_add(gerard, ["hen has teeth"], 'SHORTTERM'),
    agm_mem_deadline_of(gerard, "hen has teeth", shortterm, D),
    agm_mem_forgotten(agm_mem_gone(gerard, "hen has teeth"), D, Outcome),
    test_bool(agm_mem_holds(myself, "hen has teeth"), Robot).
test(agent_model_event, [ setup(agm_mem_fresh(20)),
                          true(Names-Outcome == [hen]-after_deadline)
                        ]) :-
    oro_add(myself, ["gerard rdf:type Human"]),
    oro_events_sync,
    agm_mem_event_when(gerard, new_instance, on_false, x, ["?x has teeth"],
                       oro_add(gerard, ["hen has teeth"], 'SHORTTERM'),
                       Names, Outcome).

:- end_tests(agm_mem_forgetting).


                 /*******************************
                 *     FORGETTING, CLOCK SET    *
                 *******************************/

%   These tests set the memory module's clock (oro_memory's test clock,
%   milliseconds since the epoch) and drive forgetting with
%   oro_memory_sync/0: what is forgotten depends on the clock they set,
%   never on the wall clock.  A 50 ms time base: SHORTTERM lives 500 ms.

agm_mem_t0(1700000000000).

agm_mem_clock(Ms) :-
    oro_memory:set_test_clock(Ms).

agm_mem_clocked :-
    agm_mem_fresh(50),
    agm_mem_t0(T0),
    agm_mem_clock(T0).

agm_mem_unclocked :-
    agm_mem_clock(system).

%   agm_mem_deadline_list(+Model, -Pairs): Deadline-Statement pairs.

agm_mem_deadline_list(Model, Pairs) :-
    agm_mem_deadlines(Model, Deadlines),
    findall(D-S, member(D-S-_, Deadlines), Pairs).

:- begin_tests(agm_mem_clock, [cleanup(agm_mem_unclocked)]).

test(deadline_from_clock, [ setup(agm_mem_clocked),
                            true(Ds == [D-"f p o"])
                          ]) :-
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    agm_mem_t0(T0),
    D is T0 + 500,
    agm_mem_deadline_list(myself, Ds).
test(forgotten_at_deadline, [ setup(agm_mem_clocked),
                              true(r(Before, After, Ds) == r(true, false, []))
                            ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    Early is T0 + 499,
    agm_mem_clock(Early),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Before),
    Due is T0 + 500,
    agm_mem_clock(Due),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), After),
    oro_memory_deadlines(myself, Ds).
test(only_due_batches, [ setup(agm_mem_clocked),
                         true(r(A, B, Ds) == r(false, true, [D2-"b p o"]))
                       ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["a p o"], 'SHORTTERM'),
    T1 is T0 + 100,
    agm_mem_clock(T1),
    oro_add(myself, ["b p o"], 'SHORTTERM'),
    D1 is T0 + 500,
    D2 is T1 + 500,
    agm_mem_clock(D1),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "a p o"), A),
    test_bool(agm_mem_holds(myself, "b p o"), B),
    agm_mem_deadline_list(myself, Ds).

%   The scheduler pops a due entry (deadline D1 of myself's short-term
%   facts) and only then forgets, under the store's write lock.  A
%   refresh of the fact in between (deadline D2) must win: forgetting
%   with the entry popped before the refresh leaves the fact and its
%   new deadline.  oro_memory:expire/3 is that second step, called here
%   with the stale entry.

test(refresh_after_pop_not_forgotten,
     [ setup(agm_mem_clocked),
       true(r(Holds, Ds, Gone, Left) == r(true, [D2-"f p o"], true, []))
     ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    D1 is T0 + 500,
    T1 is T0 + 100,
    agm_mem_clock(T1),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    D2 is T1 + 500,
    agm_mem_clock(D1),
    oro_memory:expire(myself, shortterm, [D1]),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Holds),
    agm_mem_deadline_list(myself, Ds),
    agm_mem_clock(D2),
    oro_memory_sync,
    test_bool(agm_mem_gone(myself, "f p o"), Gone),
    oro_memory_deadlines(myself, Left).

%   The same through the scheduler: this thread holds the store's write
%   lock when the clock reaches D1, so the scheduler (idle: synced
%   before) takes the wake-up, pops D1 and waits for the lock; the fact
%   is refreshed before the lock is released.  Whether or not the
%   scheduler got as far as popping D1 first (the wait for its queue to
%   be empty only makes it likely), the fact must stay.

test(refresh_while_forgetting_waits,
     [ setup(agm_mem_clocked),
       true(r(Holds, Ds) == r(true, [D2-"f p o"]))
     ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["f p o"], 'SHORTTERM'),
    D1 is T0 + 500,
    T1 is T0 + 100,
    D2 is T1 + 500,
    oro_memory_sync,
    oro_store_write(test(refresh),
                    ( agm_mem_clock(D1),
                      ignore(test_wait_until(
                                 message_queue_property(oro_memory_queue,
                                                        size(0)),
                                 2)),
                      agm_mem_clock(T1),
                      oro_add(myself, ["f p o"], 'SHORTTERM'),
                      agm_mem_clock(D1)
                    )),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Holds),
    agm_mem_deadline_list(myself, Ds).

%   A lifespan of its own (lifespan(Units), the KB-API's `lifespan`):
%   any number of units, fractions too; the fact lives in the `timed`
%   graph and goes at its deadline; re-adding it with another lifespan
%   moves the deadline; a long-term fact given a lifespan stays.

test(lifespan_forgotten_at_deadline,
     [ setup(agm_mem_clocked),
       true(r(Ds, Before, After, Left) == r([D-"f p o"-timed], true, false, []))
     ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["f p o"], lifespan(2.5)),
    D is T0 + 125,
    agm_mem_deadlines(myself, Ds),
    Early is D - 1,
    agm_mem_clock(Early),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Before),
    agm_mem_clock(D),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), After),
    oro_memory_deadlines(myself, Left).
test(lifespan_any_length,
     [ setup(agm_mem_clocked),
       true(Ds == [D1-"a p o", D2-"b p o"])
     ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["a p o"], lifespan(1)),
    oro_add(myself, ["b p o"], lifespan(1000)),
    D1 is T0 + 50,
    D2 is T0 + 50000,
    agm_mem_deadline_list(myself, Ds).
test(lifespan_readded_moves_deadline,
     [ setup(agm_mem_clocked),
       true(r(Ds, Holds) == r([D2-"f p o"], true))
     ]) :-
    agm_mem_t0(T0),
    oro_add(myself, ["f p o"], lifespan(2)),
    oro_add(myself, ["f p o"], lifespan(10)),
    D2 is T0 + 500,
    agm_mem_deadline_list(myself, Ds),
    D1 is T0 + 100,
    agm_mem_clock(D1),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(lifespan_of_long_term_fact_stays,
     [ setup(agm_mem_clocked),
       true(r(Ds, Holds) == r([], true))
     ]) :-
    oro_add(myself, ["f p o"]),
    oro_add(myself, ["f p o"], lifespan(1)),
    oro_memory_deadlines(myself, Ds),
    agm_mem_t0(T0),
    T1 is T0 + 100,
    agm_mem_clock(T1),
    oro_memory_sync,
    test_bool(agm_mem_holds(myself, "f p o"), Holds).
test(update_with_lifespan,
     [ setup(agm_mem_clocked),
       true(r(Old, New, Gone) == r(false, true, true))
     ]) :-
    oro_add(myself, ["hasMood rdf:type owl:FunctionalProperty",
                     "bob hasMood calm"]),
    oro_update(myself, ["bob hasMood angry"], lifespan(1)),
    test_bool(agm_mem_holds(myself, "bob hasMood calm"), Old),
    test_bool(agm_mem_holds(myself, "bob hasMood angry"), New),
    agm_mem_t0(T0),
    D is T0 + 50,
    agm_mem_clock(D),
    oro_memory_sync,
    test_bool(agm_mem_gone(myself, "bob hasMood angry"), Gone).
test(lifespan_not_positive, [ setup(agm_mem_fresh),
                              error(domain_error(oro_lifespan, 0))
                            ]) :-
    oro_add(myself, ["f p o"], lifespan(0)).

:- end_tests(agm_mem_clock).


                 /*******************************
                 *        SOCKET HELPERS        *
                 *******************************/

%   agm_mem_start: a server with the common-sense ontology, robot id
%   ROBOT and a 50 ms time base (noted as set by the server, then
%   forced to 50 ms whatever it was).

agm_mem_start :-
    agm_mem_stop,
    test_server_start_time_base([ commonsense(true),
                                  robot_id('ROBOT'),
                                  time_base(50)
                                ], TimeBase),
    retractall(agm_mem_started_time_base(_)),
    assertz(agm_mem_started_time_base(TimeBase)).

agm_mem_stop :-
    test_server_stop_synced.

agm_mem_server_fresh :-
    test_ok(reset, []).

%   agm_mem_socket_check(+Pattern, -Reply): check over the socket.

agm_mem_socket_check(Pattern, Reply) :-
    test_call(check, [Pattern], Reply).

agm_mem_socket_gone(Pattern) :-
    agm_mem_socket_check(Pattern, ok("false")).

%   agm_mem_socket_forgotten(+Pattern, +Statement, -Outcome): poll check
%   over the socket until Pattern is false; Outcome against the
%   short-term deadline of Statement in the robot's model.

agm_mem_socket_forgotten(Pattern, Statement, Outcome) :-
    (   agm_mem_deadline_of(myself, Statement, shortterm, D)
    ->  agm_mem_forgotten(agm_mem_socket_gone(Pattern), D, Outcome)
    ;   Outcome = no_deadline
    ).

agm_mem_socket_forgotten_by(Deadlines, Pattern, Statement, Outcome) :-
    (   memberchk(D-Statement-shortterm, Deadlines)
    ->  agm_mem_forgotten(agm_mem_socket_gone(Pattern), D, Outcome)
    ;   Outcome = no_deadline
    ).

agm_mem_socket_marker(Outcome) :-
    test_ok(add, ['[marker is set]', 'SHORTTERM']),
    agm_mem_socket_forgotten('[marker is set]', "marker is set", Outcome).

agm_mem_rs_name(Name) :-
    (   sub_string(Name, _, _, _, "rs_")
    ;   sub_string(Name, _, _, _, "Statement")
    ),
    !.


                 /*******************************
                 *     §13.12 OVER THE SOCKET   *
                 *******************************/

:- begin_tests(agm_mem_socket,
               [ setup(agm_mem_start),
                 cleanup(agm_mem_stop)
               ]).

test(time_base_option, true(TimeBase == 50)) :-
    agm_mem_started_time_base(TimeBase).
test(vector_13_12, [ setup(agm_mem_server_fresh),
                     true(r(Add, Check, Outcome, Event) ==
                          r(ok(""), ok("true"), after_deadline,
                            "[\"superman\"]"))
                   ]) :-
    test_connected(Conn,
                   ( oro_call(Conn, registerEvent,
                              ['NEW_INSTANCE', 'ON_FALSE', a,
                               '[?a rdf:type Animal]'], ok(_)),
                     oro_call(Conn, add, ['[superman rdf:type Animal]',
                                          'SHORTTERM'], Add),
                     oro_call(Conn, check, ['[superman rdf:type Animal]'],
                              Check),
                     agm_mem_socket_forgotten('[superman rdf:type Animal]',
                                              "superman rdf:type Animal",
                                              Outcome),
                     oro_next_event(Conn, E, 5)
                   )),
    (   E = event(_, Event)
    ->  true
    ;   Event = E
    ).
test(fact_checking_on_false, [ setup(agm_mem_server_fresh),
                               true(Event == "")
                             ]) :-
    test_connected(Conn,
                   ( oro_call(Conn, registerEvent,
                              ['FACT_CHECKING', 'ON_FALSE',
                               '[superman rdf:type Animal]'], ok(_)),
                     oro_call(Conn, add, ['[superman rdf:type Animal]',
                                          'SHORTTERM'], ok(_)),
                     oro_next_event(Conn, E, 5)
                   )),
    (   E = event(_, Event)
    ->  true
    ;   Event = E
    ).
test(episodic_survives, [ setup(agm_mem_server_fresh),
                          true(r(Marker, Check, Late) ==
                               r(after_deadline, ok("true"), true))
                        ]) :-
    agm_mem_now(T0),
    test_ok(add, ['[snail eats grass]', 'EPISODIC']),
    agm_mem_socket_marker(Marker),
    agm_mem_socket_check('[snail eats grass]', Check),
    agm_mem_deadline_of(myself, "snail eats grass", episodic, D),
    test_bool(D >= T0 + 300 * 50, Late).
test(unknown_profile_is_default, [ setup(agm_mem_server_fresh),
                                   true(r(Marker, Check, Ds) ==
                                        r(after_deadline, ok("true"), []))
                                 ]) :-
    test_ok(add, ['[x y z]', bogus]),
    oro_memory_deadlines(myself, Ds),
    agm_mem_socket_marker(Marker),
    agm_mem_socket_check('[x y z]', Check).
test(long_term_profiles, [ setup(agm_mem_server_fresh),
                           true(r(Marker, Check, Ds) ==
                                r(after_deadline, ok("true"), []))
                         ]) :-
    test_ok(add, ['[a1 p o]', 'LONGTERM']),
    test_ok(add, ['[a2 p o]', 'default']),
    test_ok(add, ['[a3 p o]', 'LongTerm']),
    test_ok(add, ['[a1 p o, a2 p o, a3 p o]', 'SHORTTERM']),
    oro_memory_deadlines(myself, Ds),
    agm_mem_socket_marker(Marker),
    agm_mem_socket_check('[a1 p o, a2 p o, a3 p o]', Check).
test(any_case, [ setup(agm_mem_server_fresh),
                 true(Ss-Outcomes == ["a1 p o", "a2 p o", "a3 p o"]-
                                     [after_deadline, after_deadline,
                                      after_deadline])
               ]) :-
    test_ok(add, ['[a1 p o]', shortterm]),
    test_ok(add, ['[a2 p o]', 'ShortTerm']),
    test_ok(add, ['[a3 p o]', 'SHORTTERM']),
    agm_mem_deadlines(myself, Deadlines),
    findall(S, member(_-S-shortterm, Deadlines), Ss0),
    sort(Ss0, Ss),
    maplist(agm_mem_socket_forgotten_by(Deadlines),
            ['[a1 p o]', '[a2 p o]', '[a3 p o]'],
            ["a1 p o", "a2 p o", "a3 p o"],
            Outcomes).
test(no_reification_visible, [ setup(agm_mem_server_fresh),
                               true(r(Statements, Subjects, Infos) == r([], [], []))
                             ]) :-
    test_ok(add, ['[superman rdf:type Animal]', 'SHORTTERM']),
    test_ok(add, ['[snail eats grass]', 'EPISODIC']),
    test_set_call(find, [x, '[?x rdf:type rdf:Statement]'], Statements),
    test_set_call(find, [s, '[?s ?p ?o]'], All),
    include(agm_mem_rs_name, All, Subjects),
    test_set_call(getInfos, [superman], AllInfos),
    include(agm_mem_rs_name, AllInfos, Infos).
test(short_term_for_agent, [ setup(agm_mem_server_fresh),
                             true(r(Found, Gone, Robot) ==
                                  r(ok("[\"hen\"]"), true, ok("true")))
                           ]) :-
    test_ok(add, ['[gerard rdf:type Human, hen has teeth]']),
    test_ok(addForAgent, [gerard, '[hen has teeth]', 'SHORTTERM']),
    test_call(findForAgent, [gerard, x, '[?x has teeth]'], Found),
    test_bool(test_wait_until(
               test_call(findForAgent, [gerard, x, '[?x has teeth]'],
                         ok("[]")),
               5),
              Gone),
    agm_mem_socket_check('[hen has teeth]', Robot).

:- end_tests(agm_mem_socket).
