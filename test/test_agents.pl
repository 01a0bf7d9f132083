:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(filesex)).
:- use_module(library(readutil)).
:- use_module(library(aggregate)).

/*  Tests for agent models (ORO-SPEC §6.6, §8, revise of §6.1, the
    vectors of §13.11), through the Prolog API (oro_agents/1,
    oro_revise/2, every oro_* predicate on an agent model) and over the
    socket (listAgents, *ForAgent, find/4, revise, events per agent),
    plus the replay of a recorded robot session
    (../shared/workloads/robot-session-2011.log, if present) with agent
    models for the robot and its human partner.

    What is checked: a model per agent over the shared ontology layer;
    facts and schema added to one model never leak into another;
    reasoning, find, check, lookup, taxonomy and events work per model;
    models are created for every individual that becomes an Agent in
    the robot's model, asserted or inferred; `myself`, `default` and the
    robot id name the robot's model, and in an agent's model `myself` is
    that agent; clearEvents does not stop the creation of models;
    unknown agents are errors; consistency and safe adds are per model;
    revise applies each method to the selected models.

    Tests marked blocked/1 show bugs of the implementation: the reason
    says which.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_agents.pl
*/

:- dynamic
    agm_save_dir/1,                     % Dir
    agm_started_time_base/1,            % Milliseconds
    agm_replay_conn/2.                  % Thread, Conn


                 /*******************************
                 *        PROLOG HELPERS        *
                 *******************************/

%   agm_fresh: the common-sense ontology, robot id ROBOT.

agm_fresh :-
    oro_init([robot_id('ROBOT')]).

%   agm_fresh_agents: agm_fresh with two agents, gerard (a Human: an
%   inferred Agent) and toto (an asserted Agent).

agm_fresh_agents :-
    agm_fresh,
    oro_add(myself, ["gerard rdf:type Human", "toto rdf:type Agent"]),
    oro_events_sync.

%   agm_agents(-Names): the model names once the agent watcher has seen
%   every change made so far.

agm_agents(Names) :-
    oro_events_sync,
    oro_agents(Names).

%   agm_holds(+Model, +Statement, -Bool)

agm_holds(Model, Statement, Bool) :-
    (   oro_check(Model, [Statement])
    ->  Bool = true
    ;   Bool = false
    ).

%   agm_event_to(+Queue, +Id, +Content): an oro_subscribe/7 callback.

agm_event_to(Queue, Id, Content) :-
    thread_send_message(Queue, event(Id, Content)).

%   agm_first_event(+Model, +Type, +Trigger, +Var, +Patterns, :Goal,
%   -Names): subscribe in Model, run Goal, and give the contracted
%   content of the first event (`timeout` if none comes in 5 s).

:- meta_predicate agm_first_event(+, +, +, +, +, 0, -).

agm_first_event(Model, Type, Trigger, Var, Patterns, Goal, Names) :-
    message_queue_create(Queue),
    setup_call_cleanup(
        oro_subscribe(Model, Type, Trigger, Var, Patterns,
                      agm_event_to(Queue), Id),
        ( once(Goal),
          (   thread_get_message(Queue, event(Id, Content), [timeout(5)])
          ->  test_names(Content, Names)
          ;   Names = timeout
          )
        ),
        ( oro_unsubscribe(Id),
          message_queue_destroy(Queue)
        )).


                 /*******************************
                 *      MODELS (PROLOG API)     *
                 *******************************/

:- begin_tests(agm_models).

test(robot_names, [ setup(agm_fresh),
                    true(Names == ['ROBOT', default, myself])
                  ]) :-
    agm_agents(Names).
test(asserted_agent, [ setup(agm_fresh),
                       true(Names == ['ROBOT', default, gerard, myself])
                     ]) :-
    oro_add(myself, ["gerard rdf:type Agent"]),
    agm_agents(Names).
test(inferred_agent_human, [ setup(agm_fresh),
                             true(Names == ['ROBOT', default, gerard, myself])
                           ]) :-
    oro_add(myself, ["gerard rdf:type Human"]),
    agm_agents(Names).
test(inferred_agent_domain, [ setup(agm_fresh),
                              true(Names == ['ROBOT', bob, default, myself])
                            ]) :-
    % knows has the domain Agent in the common-sense ontology.
    oro_add(myself, ["bob knows alice"]),
    agm_agents(Names).
test(subclass_axiom_makes_animals_agents,
     [ setup(agm_fresh),
       true(Before-After-Later ==
            ['ROBOT', default, myself]-
            ['ROBOT', baboon, default, kiki, myself]-
            ['ROBOT', baboon, default, kiki, myself, rex])
     ]) :-
    oro_add(myself, ["baboon rdf:type Animal", "kiki rdf:type Animal"]),
    agm_agents(Before),
    oro_add(myself, ["Animal rdfs:subClassOf Agent"]),
    agm_agents(After),
    oro_add(myself, ["rex rdf:type Animal"]),
    agm_agents(Later).
test(agents_in_the_ontology_at_start,
     [ true(Names == ['ACHILE_HUMAN1', 'JIDOKUKA_ROBOT', default, myself])
     ]) :-
    test_fixture('scenario-2011.ttl', Scenario),
    oro_init([robot_id('JIDOKUKA_ROBOT'), ontologies([Scenario])]),
    agm_agents(Names).
test(model_usable_right_after_add, [ setup(agm_fresh),
                                     true(Holds == true)
                                   ]) :-
    % No sync: naming the agent waits for its model being created.
    oro_add(myself, ["gerard rdf:type Human"]),
    oro_add(gerard, ["paris loves dancing"]),
    agm_holds(gerard, "paris loves dancing", Holds).
test(listed_right_after_add,
     [ setup(agm_fresh),
       true(memberchk(gerard, Names))
     ]) :-
    oro_add(myself, ["gerard rdf:type Human"]),
    oro_agents(Names).
test(robot_is_no_agent, [ setup(agm_fresh),
                          true(Names == ['ROBOT', default, myself])
                        ]) :-
    % myself and ROBOT are Robots, hence Agents: no model of their own.
    oro_add(myself, ["robbie owl:sameAs myself", "robbie rdf:type Robot"]),
    agm_agents(Names).
test(same_as_an_agent, [ setup(agm_fresh),
                         true(Names == ['ROBOT', default, gerard, myself])
                       ]) :-
    oro_add(myself, ["gerard rdf:type Human"]),
    oro_events_sync,
    oro_add(myself, ["gerry owl:sameAs gerard"]),
    agm_agents(Names).
test(unknown_agent, [ setup(agm_fresh),
                      error(existence_error(agent, nobody))
                    ]) :-
    oro_add(nobody, ["a b c"]).
test(unknown_agent_find, [ setup(agm_fresh),
                           error(existence_error(agent, nobody))
                         ]) :-
    oro_find(nobody, x, ["?x b c"], _).
test(names_are_case_sensitive, [ setup(agm_fresh_agents),
                                 error(existence_error(agent, 'Gerard'))
                               ]) :-
    oro_check('Gerard', ["a b c"]).
test(robot_aliases, [ setup(agm_fresh),
                      true(Holds == [true, true, true])
                    ]) :-
    oro_add('ROBOT', ["r1 p o"]),
    oro_add(default, ["r2 p o"]),
    oro_add(myself, ["r3 p o"]),
    maplist(agm_holds(myself), ["r1 p o", "r2 p o", "r3 p o"], Holds).
test(myself_is_the_agent, [ setup(agm_fresh_agents),
                            true(In-Robot == true-false)
                          ]) :-
    agm_holds(gerard, "myself owl:sameAs gerard", In),
    agm_holds(myself, "myself owl:sameAs gerard", Robot).
test(myself_as_subject, [ setup(agm_fresh_agents),
                          true(Holds == [true, false, false])
                        ]) :-
    oro_add(gerard, ["myself likes tea"]),
    agm_holds(gerard, "gerard likes tea", H1),
    agm_holds(myself, "myself likes tea", H2),
    agm_holds(toto, "myself likes tea", H3),
    Holds = [H1, H2, H3].
test(robot_in_agent_model, [ setup(agm_fresh_agents),
                             true(Holds == true)
                           ]) :-
    agm_holds(gerard, "ROBOT rdf:type Robot", Holds).
test(agent_is_not_a_robot,
     [ setup(agm_fresh_agents),
       true(Holds == false)
     ]) :-
    agm_holds(gerard, "gerard rdf:type Robot", Holds).
test(agent_may_be_human_in_own_model,
     [ setup(agm_fresh_agents),
       true(Consistent == true)
     ]) :-
    oro_add(gerard, ["myself rdf:type Human"]),
    test_bool(oro_consistent(gerard), Consistent).
test(clear_events_keeps_creation,
     [ setup(agm_fresh),
       true(Names == ['ROBOT', default, gerard, myself])
     ]) :-
    oro_clear_events(myself),
    oro_clear_events(myself, agent),
    oro_add(myself, ["gerard rdf:type Human"]),
    agm_agents(Names).
test(reset_forgets_agents,
     [ setup(agm_fresh_agents),
       true(Reset-Again == ['ROBOT', default, myself]-
                           ['ROBOT', bob, default, myself])
     ]) :-
    oro_reset,
    agm_agents(Reset),
    oro_add(myself, ["bob rdf:type Human"]),
    agm_agents(Again).
test(create_agent, [ setup(agm_fresh),
                     true(In-Names == true-['ROBOT', bob, default, myself])
                   ]) :-
    oro_name_iri(bob, Bob),
    oro_create_agent(bob, Bob),
    agm_holds(bob, "myself owl:sameAs bob", In),
    agm_agents(Names).
test(create_agent_names,                    % bob was taken for the IRI 'bob'
     [ setup(agm_fresh),
       true(In == [true, true, true])
     ]) :-
    oro_name_iri(dave, Dave),
    findall(Holds, ( member(Model-Individual-Statement,
                            [ bob-bob-"myself owl:sameAs bob",
                              carol-(oro:carol)-"myself owl:sameAs carol",
                              dave-Dave-"myself owl:sameAs dave"
                            ]),
                     oro_create_agent(Model, Individual),
                     agm_holds(Model, Statement, Holds)
                   ), In).

:- end_tests(agm_models).


                 /*******************************
                 *    ISOLATION (PROLOG API)    *
                 *******************************/

:- begin_tests(agm_isolation).

test(facts, [ setup(agm_fresh_agents),
              true(Holds == [true, false, false])
            ]) :-
    oro_add(gerard, ["paris loves dancing"]),
    maplist(agm_model_holds("paris loves dancing"), [gerard, myself, toto],
            Holds).
test(robot_facts_not_copied, [ setup(agm_fresh_agents),
                               true(Holds == [true, false])
                             ]) :-
    oro_add(myself, ["gerard likes tea"]),
    maplist(agm_model_holds("gerard likes tea"), [myself, gerard], Holds).
test(subclass_axiom, [ setup(agm_fresh_agents),
                       true(Holds == [true, false, false])
                     ]) :-
    oro_add(gerard, ["Spork rdfs:subClassOf Tableware"]),
    maplist(agm_model_holds("Spork rdfs:subClassOf Tableware"),
            [gerard, myself, toto], Holds).
test(subclass_inference, [ setup(agm_fresh_agents),
                           true(Holds == [true, false])
                         ]) :-
    % The robot's closures are computed first, then gerard's schema changes.
    oro_add(myself, ["spork1 rdf:type Spork"]),
    agm_holds(myself, "spork1 rdf:type Artifact", _),
    oro_add(gerard, ["Spork rdfs:subClassOf Tableware",
                     "spork1 rdf:type Spork"]),
    maplist(agm_model_holds("spork1 rdf:type Artifact"), [gerard, myself],
            Holds).
test(subclass_inference_robot_side, [ setup(agm_fresh_agents),
                                      true(Holds == [true, false])
                                    ]) :-
    oro_add(gerard, ["spork1 rdf:type Spork"]),
    agm_holds(gerard, "spork1 rdf:type Artifact", _),
    oro_add(myself, ["Spork rdfs:subClassOf Tableware",
                     "spork1 rdf:type Spork"]),
    maplist(agm_model_holds("spork1 rdf:type Artifact"), [myself, gerard],
            Holds).
test(find, [ setup(agm_fresh_agents),
             true(G-M == [paris]-[])
           ]) :-
    oro_add(gerard, ["paris loves dancing"]),
    test_find(gerard, x, ["?x loves dancing"], G),
    test_find(myself, x, ["?x loves dancing"], M).
test(taxonomy, [ setup(agm_fresh_agents),
                 true(r(GS, MS, GI, MI) ==
                      r(true, false, ['spork1'], []))
               ]) :-
    oro_add(gerard, ["Spork rdfs:subClassOf Tableware",
                     "spork1 rdf:type Spork"]),
    oro_add(myself, ["spork1 rdf:type Spork"]),
    oro_name_iri('Tableware', Tableware),
    oro_name_iri('Spork', Spork),
    oro_subclasses(gerard, Tableware, GSubs),
    oro_subclasses(myself, Tableware, MSubs),
    test_bool(memberchk(Spork, GSubs), GS),
    test_bool(memberchk(Spork, MSubs), MS),
    oro_instances(gerard, Tableware, GIs),
    oro_instances(myself, Tableware, MIs),
    test_names(GIs, GI),
    test_names(MIs, MI).
test(taxonomy_unknown_class_elsewhere,
     [ setup(agm_fresh_agents),
       error(existence_error(class, _))
     ]) :-
    oro_add(gerard, ["Spork rdfs:subClassOf Tableware"]),
    oro_name_iri('Spork', Spork),
    oro_superclasses(myself, Spork, _).
test(lookup, [ setup(agm_fresh_agents),
               true(G-M == [paris-instance]-[])
             ]) :-
    oro_add(gerard, ["paris loves dancing", "paris rdfs:label \"Paname\""]),
    oro_lookup(gerard, "paname", G0),
    oro_lookup(myself, "paname", M),
    findall(N-K, ( member(R-K, G0), oro_iri_name(R, N) ), G).
test(runtime_functional_property, [ setup(agm_fresh_agents),
                                    true(G-M == [fido]-[fido, rex])
                                  ]) :-
    oro_add(gerard, ["hasPet rdf:type owl:FunctionalProperty"]),
    forall(member(Model, [gerard, myself]),
           ( oro_update(Model, ["ann hasPet rex"]),
             oro_update(Model, ["ann hasPet fido"])
           )),
    test_find(gerard, x, ["ann hasPet ?x"], G),
    test_find(myself, x, ["ann hasPet ?x"], M).
test(remove, [ setup(agm_fresh_agents),
               true(Holds == [false, true, true])
             ]) :-
    forall(member(Model, [gerard, myself, toto]),
           oro_add(Model, ["cup1 isOn table1"])),
    oro_remove(gerard, ["cup1 isOn table1"]),
    maplist(agm_model_holds("cup1 isOn table1"), [gerard, myself, toto],
            Holds).
test(clear_pattern, [ setup(agm_fresh_agents),
                      true(G-M == []-[table1])
                    ]) :-
    forall(member(Model, [gerard, myself]),
           oro_add(Model, ["cup1 isOn table1"])),
    oro_clear(gerard, ["cup1 ?p ?o"]),
    test_find(gerard, o, ["cup1 isOn ?o"], G),
    test_find(myself, o, ["cup1 isOn ?o"], M).
test(ontology_fact_removed_in_one_model,
     [ setup(agm_fresh_agents),
       true(Holds == [false, true])
     ]) :-
    oro_remove(gerard, ["Human rdfs:subClassOf EmbodiedAgent"]),
    maplist(agm_model_holds("Human rdfs:subClassOf EmbodiedAgent"),
            [gerard, myself], Holds).
test(agent_in_agent_model_makes_no_model,
     [ setup(agm_fresh_agents),
       true(Names == ['ROBOT', default, gerard, myself, toto])
     ]) :-
    % Only the robot's model creates agent models.
    oro_add(gerard, ["kevin rdf:type Human"]),
    agm_agents(Names).
test(consistency, [ setup(agm_fresh_agents),
                    true(Consistent == [false, true, true])
                  ]) :-
    % BodyPart is disjoint with Agent.
    oro_add(toto, ["hand1 rdf:type BodyPart", "hand1 rdf:type Agent"]),
    maplist(agm_consistent, [toto, myself, gerard], Consistent).
test(safe_add, [ setup(agm_fresh_agents),
                 true(r(T, G, TB, TA, GA) == r(false, true, true, false, true))
               ]) :-
    oro_safe_add(toto, ["hand1 rdf:type BodyPart", "hand1 rdf:type Agent"],
                 longterm, T),
    oro_safe_add(gerard, ["hand1 rdf:type Agent"], longterm, G),
    agm_holds(toto, "hand1 rdf:type BodyPart", TB),
    agm_holds(toto, "hand1 rdf:type Agent", TA),
    agm_holds(gerard, "hand1 rdf:type Agent", GA).
test(revise_safe_add, [ setup(agm_fresh_agents),
                        true(T-G == false-true)
                      ]) :-
    oro_add(toto, ["hand1 rdf:type BodyPart"]),
    oro_revise(["hand1 rdf:type Agent"],
               _{method:"safe_add", models:["toto", "gerard"]}),
    agm_holds(toto, "hand1 rdf:type Agent", T),
    agm_holds(gerard, "hand1 rdf:type Agent", G).
test(events_agent_model, [ setup(agm_fresh_agents),
                           true(Names == [hen])
                         ]) :-
    agm_first_event(gerard, new_instance, on_true, x, ["?x has teeth"],
                    ( oro_add(myself, ["chicken has teeth"]),
                      oro_add(toto, ["duck has teeth"]),
                      oro_add(gerard, ["hen has teeth"])
                    ),
                    Names).
test(events_robot_model, [ setup(agm_fresh_agents),
                           true(Names == [chicken])
                         ]) :-
    agm_first_event(myself, new_instance, on_true, x, ["?x has teeth"],
                    ( oro_add(gerard, ["hen has teeth"]),
                      oro_add(myself, ["chicken has teeth"])
                    ),
                    Names).
test(events_fact_checking, [ setup(agm_fresh_agents),
                             true(Names == [])
                           ]) :-
    agm_first_event(gerard, fact_checking, on_true, '', ["chicken has teeth"],
                    oro_add(gerard, ["chicken has teeth"]),
                    Names).
test(memory_per_model, [ setup(agm_fresh_agents),
                         true(G-M == [rdf(hen, has, teeth)]-[])
                       ]) :-
    oro_add(gerard, ["hen has teeth"], 'SHORTTERM'),
    oro_memory_deadlines(gerard, GD),
    oro_memory_deadlines(myself, M),
    findall(rdf(S, P, O),
            ( member(_-rdf(S0, P0, O0)-_, GD),
              maplist(oro_iri_name, [S0, P0, O0], [S, P, O])
            ),
            G).

:- end_tests(agm_isolation).

agm_consistent(Model, Bool) :-
    test_bool(oro_consistent(Model), Bool).

agm_model_holds(Statement, Model, Bool) :-
    agm_holds(Model, Statement, Bool).


                 /*******************************
                 *     REVISE (PROLOG API)      *
                 *******************************/

:- begin_tests(agm_revise).

test(add_list, [ setup(agm_fresh_agents),
                 true(Holds == [true, false, false])
               ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:["gerard", "nobody"]}),
    agm_where("r1 p o", Holds).
test(add_string, [ setup(agm_fresh_agents),
                   true(Holds == [false, false, true])
                 ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:"toto"}),
    agm_where("r1 p o", Holds).
test(add_all, [ setup(agm_fresh_agents),
                true(Holds == [true, true, true])
              ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:"all"}),
    agm_where("r1 p o", Holds).
test(add_empty_list, [ setup(agm_fresh_agents),
                       true(Holds == [true, true, true])
                     ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:[]}),
    agm_where("r1 p o", Holds).
test(add_models_missing, [ setup(agm_fresh_agents),
                           true(Holds == [false, true, false])
                         ]) :-
    oro_revise(["r1 p o"], _{method:"add"}),
    agm_where("r1 p o", Holds).
test(add_robot_alias, [ setup(agm_fresh_agents),
                        true(Holds == [false, true, false])
                      ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:["ROBOT", "default"]}),
    agm_where("r1 p o", Holds).
test(safe_add, [ setup(agm_fresh_agents),
                 true(Holds == [true, true, false])
               ]) :-
    oro_revise(["r1 p o"], _{method:"safe_add", models:["gerard", "myself"]}),
    agm_where("r1 p o", Holds).
test(retract, [ setup(agm_fresh_agents),
                true(Holds == [false, true, false])
              ]) :-
    oro_revise(["r1 p o"], _{method:"add", models:"all"}),
    oro_revise(["r1 p o"], _{method:"retract", models:["gerard", "toto"]}),
    agm_where("r1 p o", Holds).
test(update, [ setup(agm_fresh_agents),
               true(G-M == [false]-[true])
             ]) :-
    oro_revise(["ball isMoving true"], _{method:"add", models:"all"}),
    oro_revise(["ball isMoving false"], _{method:"update", models:"gerard"}),
    test_find(gerard, v, ["ball isMoving ?v"], G),
    test_find(myself, v, ["ball isMoving ?v"], M).
test(any_case_and_profile, [ setup(agm_fresh_agents),
                             true(N-Holds == 1-[true, false, false])
                           ]) :-
    oro_revise(["r1 p o"], _{method:"ADD", models:["gerard"],
                             memory_profile:"shortTerm"}),
    oro_memory_deadlines(gerard, Deadlines),
    length(Deadlines, N),
    agm_where("r1 p o", Holds).
test(revision_not_implemented,
     [ setup(agm_fresh_agents),
       error(existence_error(oro_revision_method, revision))
     ]) :-
    oro_revise(["r1 p o"], _{method:"revision", models:"all"}).
test(safe_update_not_implemented,
     [ setup(agm_fresh_agents),
       error(existence_error(oro_revision_method, safe_update))
     ]) :-
    oro_revise(["r1 p o"], _{method:"safe_update"}).
test(bad_method, [ setup(agm_fresh_agents),
                   error(domain_error(oro_revision_method, "insert"))
                 ]) :-
    oro_revise(["r1 p o"], _{method:"insert"}).
test(missing_method, [ setup(agm_fresh_agents),
                       error(domain_error(oro_revision_method, _))
                     ]) :-
    oro_revise(["r1 p o"], _{models:"all"}).
test(bad_profile, [ setup(agm_fresh_agents),
                    error(domain_error(oro_memory_profile, "forever"))
                  ]) :-
    oro_revise(["r1 p o"], _{method:"add", memory_profile:"forever"}).
test(bad_statement_changes_nothing,
     [ setup(agm_fresh_agents),
       true(Holds == [false, false, false])
     ]) :-
    catch(oro_revise(["r1 p o", "r2 p"], _{method:"add", models:"all"}),
          error(syntax_error(_), _),
          true),
    agm_where("r1 p o", Holds).

:- end_tests(agm_revise).

%   agm_where(+Statement, -Holds): whether Statement holds in gerard,
%   myself and toto.

agm_where(Statement, Holds) :-
    maplist(agm_model_holds(Statement), [gerard, myself, toto], Holds).


                 /*******************************
                 *        SOCKET HELPERS        *
                 *******************************/

%   agm_start(+Options): start a server on a free port of 127.0.0.1
%   (stopping a leftover one first).  The memory time base it set is
%   noted, then forced to 50 ms whatever it is.

agm_start(Options) :-
    agm_stop_server,
    test_server_start_time_base(Options, TimeBase),
    retractall(agm_started_time_base(_)),
    assertz(agm_started_time_base(TimeBase)).

%   The server of §13.11: the common-sense ontology, robot id ROBOT, a
%   50 ms time base and a save directory of its own.

agm_start_commonsense :-
    agm_stop,
    tmp_file(agm_save, Dir),
    make_directory(Dir),
    assertz(agm_save_dir(Dir)),
    agm_start([ commonsense(true),
                robot_id('ROBOT'),
                time_base(50),
                save_dir(Dir)
              ]).

agm_stop :-
    agm_stop_server,
    forall(retract(agm_save_dir(Dir)),
           catch(delete_directory_and_contents(Dir), _, true)).

agm_stop_server :-
    test_server_stop_synced.

%   agm_server_fresh: back to the state the server started in.

agm_server_fresh :-
    test_ok(reset, []).

%   agm_list_agents(-Names): listAgents as a sorted list of strings.

agm_list_agents(Names) :-
    test_set_call(listAgents, [], Names).

agm_agent_listed(Name) :-
    agm_list_agents(Names),
    memberchk(Name, Names).

%   agm_not_found(+Name, -Reply): the AgentNotFoundException reply for
%   Name.

agm_not_found(Name, error("laas.openrobots.ontology.exceptions.AgentNotFoundException",
                          Message)) :-
    format(string(Message), "I couldn't find the agent ~w.", [Name]).

%   agm_forgotten_for(+Agent, +Var, +Pattern): findForAgent answers [].

agm_forgotten_for(Agent, Var, Pattern) :-
    test_call(findForAgent, [Agent, Var, Pattern], ok("[]")).

%   agm_values_of_a1(+Agent, -Values): the values of a1 p and a1 q in
%   the model of Agent.

agm_values_of_a1(Agent, [P, Q]) :-
    test_set_call(findForAgent, [Agent, x, '[a1 p ?x]'], P),
    test_set_call(findForAgent, [Agent, x, '[a1 q ?x]'], Q).

agm_saved_text(File, Text) :-
    agm_save_dir(Dir),
    directory_file_path(Dir, File, Path),
    read_file_to_string(Path, Text, []).


                 /*******************************
                 *     §13.11 OVER THE SOCKET   *
                 *******************************/

:- begin_tests(agm_socket,
               [ setup(agm_start_commonsense),
                 cleanup(agm_stop)
               ]).

test(time_base_option, true(TimeBase == 50)) :-
    agm_started_time_base(TimeBase).
test(list_agents_fresh, [ setup(agm_server_fresh),
                          true(Reply == ok("[\"ROBOT\",\"default\",\"myself\"]"))
                        ]) :-
    test_call(listAgents, [], Reply).
test(list_agents_is_a_json_list, [ setup(agm_server_fresh),
                                   true(Names == ["ROBOT", "default", "myself"])
                                 ]) :-
    agm_list_agents(Names).
test(vector_13_11, [ setup(agm_server_fresh),
                     true(Replies == [ ok(""), ok(""), ok("[\"paris\"]"),
                                       ok("[]"), NotFound ])
                   ]) :-
    agm_not_found(nobody, NotFound),
    test_calls([ add-['[gerard rdf:type Agent]'],
                 addForAgent-[gerard, '[paris loves dancing]'],
                 findForAgent-[gerard, x, '[?x loves dancing]'],
                 find-[x, '[?x loves dancing]'],
                 addForAgent-[nobody, '[a b c]']
               ], Replies).
test(find_for_agent_junit,
     [ setup(agm_server_fresh),
       true(Replies-Empty ==
            [ok(""), ok(""), ok("[\"gorilla\"]"), ok("[]")]-
            "laas.openrobots.ontology.exceptions.OntologyServerException")
     ]) :-
    test_calls([ add-['[toto rdf:type Agent]'],
                 addForAgent-[toto, '[gorilla eats banana_tree, gorilla isFemale false, elephant weight 1547.32]'],
                 findForAgent-[toto, mysterious, '[?mysterious eats banana_tree, ?mysterious isFemale false]'],
                 findForAgent-[toto, '""', '[]'],
                 findForAgent-[toto, '?mysterious', '[]']
               ], [R1, R2, R3, R4, R5]),
    test_error_name(R4, Empty),
    Replies = [R1, R2, R3, R5].
test(find_for_agent_filters,
     [ setup(agm_server_fresh),
       true(Replies == [ok(""), ok(""), ok("[\"elephant\"]"),
                        ok("[\"elephant\"]")])
     ]) :-
    test_calls([ add-['[toto rdf:type Agent]'],
                 addForAgent-[toto, '[gorilla eats banana_tree, elephant weight 1547.32, gorilla weight 150]'],
                 findForAgent-[toto, mysterious, '[?mysterious oro:weight ?value]', '[?value >= 1000]'],
                 find-['[mysterious]', '[?mysterious oro:weight ?value]', '[?value >= 1000]', '[toto]']
               ], Replies).
test(find_kb_api, [ setup(agm_server_fresh),
                    true(Replies == [ ok(""), ok(""), ok(""),
                                      ok("[\"paris\"]"), ok("[\"rome\"]"),
                                      ok("[\"rome\"]") ])
                  ]) :-
    test_calls([ add-['[gerard rdf:type Agent]'],
                 addForAgent-[gerard, '[paris loves dancing]'],
                 add-['[rome loves dancing]'],
                 find-['[x]', '[?x loves dancing]', '[]', '[gerard]'],
                 find-['[x]', '[?x loves dancing]', '[]', '[]'],
                 find-['[x]', '[?x loves dancing]', null, null]
               ], Replies).
test(get_infos_for_agent,
     [ setup(agm_server_fresh),
       true(r(Before, N, Likes, RobotLikes) ==
            r("com.hp.hpl.jena.shared.NotFoundException", 2, true, false))
     ]) :-
    test_ok(add, ['[Animal rdfs:subClassOf Agent, baboon rdf:type Animal]']),
    test_call(getInfosForAgent, [baboon, banana], R1),
    test_error_name(R1, Before),
    test_ok(addForAgent, [baboon, '[baboon likes banana]']),
    test_set_call(getInfosForAgent, [baboon, banana], Infos),
    length(Infos, N),
    test_set_call(getInfosForAgent, [baboon, baboon], AgentInfos),
    test_bool(memberchk("baboon likes banana", AgentInfos), Likes),
    test_set_call(getInfos, [baboon], RobotInfos),
    test_bool(memberchk("baboon likes banana", RobotInfos), RobotLikes).
test(lookup_for_agent, [ setup(agm_server_fresh),
                         true(G-M == [["paris", "INSTANCE"]]-[])
                       ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_ok(addForAgent, [gerard, '[paris loves dancing, paris rdfs:label "Paname"]']),
    test_set_call(lookupForAgent, [gerard, 'Paname'], G),
    test_set_call(lookup, ['Paname'], M).
test(events_per_agent, [ setup(agm_server_fresh),
                         true(Replies-Ids == [ok(""), ok(""), ok(""), ok("")]-
                                             [Marker, Teeth])
                       ]) :-
    % The vector of §13.11, with a second watcher on gerard's model to
    % show the order of events: a firing caused by the robot-model add
    % would come before the marker's.
    test_ok(add, ['[gerard rdf:type Agent]']),
    test_connected(Conn,
                   ( oro_call(Conn, registerEventForAgent,
                              [gerard, 'FACT_CHECKING', 'ON_TRUE',
                               '[chicken has teeth]'], ok(Teeth)),
                     oro_call(Conn, registerEventForAgent,
                              [gerard, 'FACT_CHECKING', 'ON_TRUE',
                               '[marker is set]'], ok(Marker)),
                     oro_call(Conn, add, ['[chicken has teeth]'], R1),
                     oro_call(Conn, addForAgent, [gerard, '[marker is set]'], R2),
                     oro_call(Conn, addForAgent, [gerard, '[chicken has teeth]'], R3),
                     oro_call(Conn, add, ['[chicken has feathers]'], R4),
                     oro_next_event(Conn, E1, 5),
                     oro_next_event(Conn, E2, 5)
                   )),
    Replies = [R1, R2, R3, R4],
    maplist(agm_event_id, [E1, E2], Ids).
test(events_robot_model_only, [ setup(agm_server_fresh),
                                true(Event == "[\"chicken\"]")
                              ]) :-
    test_ok(add, ['[gerard rdf:type Agent]']),
    test_connected(Conn,
                   ( oro_call(Conn, registerEvent,
                              ['NEW_INSTANCE', 'ON_TRUE', x, '[?x has teeth]'],
                              ok(_)),
                     oro_call(Conn, addForAgent, [gerard, '[hen has teeth]'], ok(_)),
                     oro_call(Conn, add, ['[chicken has teeth]'], ok(_)),
                     oro_next_event(Conn, E, 5)
                   )),
    agm_event_content(E, Event).
test(new_instance_for_agent, [ setup(agm_server_fresh),
                               true(Event == "[\"hen\"]")
                             ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_connected(Conn,
                   ( oro_call(Conn, registerEventForAgent,
                              [gerard, 'NEW_INSTANCE', 'ON_TRUE', x,
                               '[?x has teeth]'], ok(_)),
                     oro_call(Conn, add, ['[chicken has teeth]'], ok(_)),
                     oro_call(Conn, addForAgent, [gerard, '[hen has teeth]'], ok(_)),
                     oro_next_event(Conn, E, 5)
                   )),
    agm_event_content(E, Event).
test(listed_right_after_add,
     [ setup(agm_server_fresh),
       true(memberchk("baboon", Names))
     ]) :-
    test_connected(Conn,
                   ( oro_call(Conn, add, ['[baboon rdf:type Animal, Animal rdfs:subClassOf Agent]'], ok(_)),
                     oro_call(Conn, listAgents, [], Reply)
                   )),
    test_set(Reply, Names).
test(listed_eventually, [ setup(agm_server_fresh),
                          true(Names == ["ROBOT", "baboon", "default",
                                         "kiki", "myself"])
                        ]) :-
    test_ok(add, ['[baboon rdf:type Animal, kiki rdf:type Animal]']),
    test_ok(add, ['[Animal rdfs:subClassOf Agent]']),
    test_wait_until(( agm_agent_listed("baboon"),
                      agm_agent_listed("kiki")
                    ), 5),
    agm_list_agents(Names).
test(robot_aliases, [ setup(agm_server_fresh),
                      true(Set == ["r1", "r2", "r3"])
                    ]) :-
    test_ok(addForAgent, ['ROBOT', '[r1 p o]']),
    test_ok(addForAgent, [default, '[r2 p o]']),
    test_ok(addForAgent, [myself, '[r3 p o]']),
    test_set_call(find, [x, '[?x p o]'], Set).
test(myself_in_agent_model, [ setup(agm_server_fresh),
                              true(G-M == ["gerard", "myself"]-["ROBOT", "myself"])
                            ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_set_call(findForAgent, [gerard, x, '[myself owl:sameAs ?x]'], G),
    test_set_call(findForAgent, [myself, x, '[myself owl:sameAs ?x]'], M).
test(case_sensitive, [ setup(agm_server_fresh),
                       true(Reply == NotFound)
                     ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    agm_not_found('Gerard', NotFound),
    test_call(addForAgent, ['Gerard', '[a b c]'], Reply).
test(unknown_agent_everywhere, [ setup(agm_server_fresh),
                                 true(Bad == [])
                               ]) :-
    agm_not_found(nobody, NotFound),
    Requests = [ addForAgent-[nobody, '[a b c]'],
                 addForAgent-[nobody, '[a b c]', 'SHORTTERM'],
                 safeAddForAgent-[nobody, '[a b c]'],
                 safeAddForAgent-[nobody, '[a b c]', 'EPISODIC'],
                 removeForAgent-[nobody, '[a b c]'],
                 clearForAgent-[nobody, '[a ?b ?c]'],
                 updateForAgent-[nobody, '[a b c]'],
                 findForAgent-[nobody, x, '[?x b c]'],
                 findForAgent-[nobody, x, '[?x b c]', '[]'],
                 find-['[x]', '[?x b c]', '[]', '[nobody]'],
                 getInfosForAgent-[nobody, a],
                 lookupForAgent-[nobody, a],
                 save-[nobody, 'nobody.owl'],
                 registerEventForAgent-[nobody, 'FACT_CHECKING', 'ON_TRUE', '[a b c]'],
                 registerEventForAgent-[nobody, 'NEW_INSTANCE', 'ON_TRUE', x, '[?x b c]'],
                 clearEventsForAgent-[nobody],
                 clearEvent-[nobody, '0b5a8a9e-3d1c-4c2e-9d7e-2f1a6b3c4d5e'],
                 checkConsistencyForAgent-[nobody]
               ],
    test_calls(Requests, Replies),
    findall(M-R, ( nth1(I, Requests, M-_),
                   nth1(I, Replies, R),
                   R \== NotFound
                 ), Bad).
test(remove_for_agent, [ setup(agm_server_fresh),
                         true(G-M == [[], ["b2"]]-[["b1"], ["b2"]])
                       ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_ok(addForAgent, [gerard, '[a1 p b1, a1 q b2]']),
    test_ok(add, ['[a1 p b1, a1 q b2]']),
    test_ok(removeForAgent, [gerard, '[a1 p ?x]']),
    agm_values_of_a1(gerard, G),
    agm_values_of_a1(myself, M).
test(clear_for_agent, [ setup(agm_server_fresh),
                        true(G-M == [[], []]-[["b1"], ["b2"]])
                      ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_ok(addForAgent, [gerard, '[a1 p b1, a1 q b2]']),
    test_ok(add, ['[a1 p b1, a1 q b2]']),
    test_ok(clearForAgent, [gerard, '[a1 ?p ?o]']),
    agm_values_of_a1(gerard, G),
    agm_values_of_a1(myself, M).
test(update_for_agent, [ setup(agm_server_fresh),
                         true(G-M == ["false"]-["true"])
                       ]) :-
    test_ok(add, ['[gerard rdf:type Human, ball isMoving true]']),
    test_ok(addForAgent, [gerard, '[ball isMoving true]']),
    test_ok(updateForAgent, [gerard, '[ball isMoving false]']),
    test_set_call(findForAgent, [gerard, v, '[ball isMoving ?v]'], G),
    test_set_call(find, [v, '[ball isMoving ?v]'], M).
test(reasoning_per_model, [ setup(agm_server_fresh),
                            true(G-M == ["spork1"]-[])
                          ]) :-
    test_ok(add, ['[gerard rdf:type Human, spork1 rdf:type Spork]']),
    test_ok(addForAgent, [gerard, '[Spork rdfs:subClassOf Tableware, spork1 rdf:type Spork]']),
    test_set_call(findForAgent, [gerard, x, '[?x rdf:type Artifact]'], G),
    test_set_call(find, [x, '[?x rdf:type Artifact]'], M).
test(safe_add_for_agent, [ setup(agm_server_fresh),
                           true(Replies == [ok(""), ok("true"), ok("true"),
                                            ok("[\"a\",\"b\"]")])
                         ]) :-
    test_calls([ add-['[gerard rdf:type Human]'],
                 safeAddForAgent-[gerard, '[a p o]'],
                 safeAddForAgent-[gerard, '[b p o]', 'EPISODIC'],
                 findForAgent-[gerard, x, '[?x p o]']
               ], Replies).
test(consistency_per_agent, [ setup(agm_server_fresh),
                              true(Replies == [ ok(""), ok("true"), ok(""),
                                                ok("false"), ok("true"),
                                                ok("true") ])
                            ]) :-
    test_calls([ add-['[gerard rdf:type Human, toto rdf:type Agent]'],
                 checkConsistencyForAgent-[toto],
                 addForAgent-[toto, '[hand1 rdf:type BodyPart, hand1 rdf:type Agent]'],
                 checkConsistencyForAgent-[toto],
                 checkConsistencyForAgent-[gerard],
                 checkConsistency-[]
               ], Replies).
test(safe_add_for_agent_rejects,
     [ setup(agm_server_fresh),
       true(Replies-G-T == [ ok(""), ok("false"), ok("true"), ok("true") ]-
                           true-false)
     ]) :-
    test_calls([ add-['[gerard rdf:type Human, toto rdf:type Agent]'],
                 safeAddForAgent-[toto, '[hand1 rdf:type BodyPart, hand1 rdf:type Agent]'],
                 safeAddForAgent-[gerard, '[hand1 rdf:type Agent]', 'EPISODIC'],
                 checkConsistencyForAgent-[toto]
               ], Replies),
    test_set_call(findForAgent, [gerard, x, '[?x rdf:type Agent]'], GAgents),
    test_bool(memberchk("hand1", GAgents), G),
    test_set_call(findForAgent, [toto, x, '[?x rdf:type Agent]'], TAgents),
    test_bool(memberchk("hand1", TAgents), T).
test(add_for_agent_short_term, [ setup(agm_server_fresh),
                                 true(Found-Gone-Long == ["a"]-true-["l"])
                               ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_ok(addForAgent, [gerard, '[l p o]', 'LONGTERM']),
    test_ok(addForAgent, [gerard, '[a q o]', 'SHORTTERM']),
    test_set_call(findForAgent, [gerard, x, '[?x q o]'], Found),
    test_bool(test_wait_until(agm_forgotten_for(gerard, x, '[?x q o]'), 5), Gone),
    test_set_call(findForAgent, [gerard, x, '[?x p o]'], Long).
test(save_agent_model, [ setup(agm_server_fresh),
                         true(r(Reply, Dancing, Tea) == r(ok(""), true, false))
                       ]) :-
    test_ok(add, ['[gerard rdf:type Human, gerard drinks robot_only_tea]']),
    test_ok(addForAgent, [gerard, '[paris loves dancing]']),
    test_call(save, [gerard, 'gerard.owl'], Reply),
    agm_saved_text('gerard.owl', Text),
    test_bool(sub_string(Text, _, _, _, "dancing"), Dancing),
    test_bool(sub_string(Text, _, _, _, "robot_only_tea"), Tea).
test(clear_events_keeps_creation, [ setup(agm_server_fresh),
                                    true(Replies == [ok(""), ok(""), ok(""), ok(""),
                                                     ok("[\"paris\"]")])
                                  ]) :-
    test_calls([ clearEvents-[],
                 clearEventsForAgent-[myself],
                 add-['[gerard rdf:type Human]'],
                 addForAgent-[gerard, '[paris loves dancing]'],
                 findForAgent-[gerard, x, '[?x loves dancing]']
               ], Replies).
test(reset_discards_agents, [ setup(agm_server_fresh),
                              true(Reply-Names == NotFound-["ROBOT", "default", "myself"])
                            ]) :-
    test_ok(add, ['[gerard rdf:type Human]']),
    test_ok(addForAgent, [gerard, '[paris loves dancing]']),
    test_ok(reset, []),
    agm_not_found(gerard, NotFound),
    test_call(addForAgent, [gerard, '[paris loves dancing]'], Reply),
    agm_list_agents(Names).

%   clearEvent(agent, id).  That nothing fired is shown by a sentinel
%   watcher in the same registry and model (agm_marker/4): the next
%   event must be its firing for a new marker.

test(clear_event_for_agent,
     [ setup(agm_server_fresh),
       true(Got == [ok(""), S-"[\"agm_m1\"]", EventNotFound, AgentNotFound])
     ]) :-
    test_ok(add, ['[gerard rdf:type Agent]']),
    test_connected(Conn,
                   ( oro_call(Conn, registerEventForAgent,
                              [gerard, 'FACT_CHECKING', 'ON_TRUE',
                               '[chicken has teeth]'], ok(U)),
                     agm_sentinel(Conn, gerard, S),
                     oro_call(Conn, clearEvent, [gerard, U], R1),
                     oro_call(Conn, addForAgent, [gerard, '[chicken has teeth]'], ok(_)),
                     agm_marker(Conn, gerard, agm_m1, Next),
                     oro_call(Conn, clearEvent, [gerard, U], R2),
                     oro_call(Conn, clearEvent, [nobody, U], R3)
                   )),
    agm_event_not_found(U, EventNotFound),
    agm_not_found(nobody, AgentNotFound),
    Got = [R1, Next, R2, R3].
test(clear_event_for_agent_keeps_registries_apart,
     [ setup(agm_server_fresh),
       true(Got == Expected)
     ]) :-
    % A plain registerEvent watcher is not in the registry of
    % clearEvent(agent, id), nor is gerard's in the robot's: both stay.
    test_ok(add, ['[gerard rdf:type Agent]']),
    test_connected(Conn,
                   ( oro_call(Conn, registerEvent,
                              ['FACT_CHECKING', 'ON_TRUE', '[chicken has teeth]'],
                              ok(P)),
                     oro_call(Conn, registerEventForAgent,
                              [gerard, 'FACT_CHECKING', 'ON_TRUE',
                               '[chicken has teeth]'], ok(G)),
                     oro_call(Conn, clearEvent, [myself, P], R1),
                     oro_call(Conn, clearEvent, [myself, G], R2),
                     oro_call(Conn, add, ['[chicken has teeth]'], ok(_)),
                     oro_next_event(Conn, event(Id, Content), 5),
                     oro_call(Conn, clearEvent, [P], R3),       % plain: found
                     oro_call(Conn, clearEvent, [gerard, P], R4)
                   )),
    agm_event_not_found(P, PlainNotFound),
    agm_event_not_found(G, GerardNotFound),
    Got = [R1, R2, Id-Content, R3, R4],
    Expected = [PlainNotFound, GerardNotFound, P-"", ok(""), PlainNotFound].
test(event_for_agent_aliases,
     [ setup(agm_server_fresh),
       true(Got == [same, same, [U-"[\"bob\"]"], ok(""), S-"[\"agm_m2\"]",
                    EventNotFound])
     ]) :-
    % default, the robot id and myself name one model: one watcher.
    test_connected(Conn,
                   ( oro_call(Conn, registerEventForAgent,
                              [default, 'NEW_INSTANCE', 'ON_TRUE', x,
                               '[?x likes tea]'], ok(U)),
                     oro_call(Conn, registerEventForAgent,
                              ['ROBOT', 'NEW_INSTANCE', 'ON_TRUE', x,
                               '[?x likes tea]'], ok(U2)),
                     oro_call(Conn, registerEventForAgent,
                              [myself, 'NEW_INSTANCE', 'ON_TRUE', x,
                               '[?x likes tea]'], ok(U3)),
                     agm_sentinel(Conn, myself, S),
                     oro_call(Conn, add, ['[bob likes tea]'], ok(_)),
                     agm_marker(Conn, myself, agm_m1, First),
                     agm_events_before(Conn, S, First, Events),
                     oro_call(Conn, clearEvent, ['ROBOT', U], R1),
                     oro_call(Conn, add, ['[bill likes tea]'], ok(_)),
                     agm_marker(Conn, myself, agm_m2, Next),
                     oro_call(Conn, clearEvent, [default, U], R2)
                   )),
    maplist(agm_same(U), [U2, U3], Same),
    agm_event_not_found(U, EventNotFound),
    append(Same, [Events, R1, Next, R2], Got).

:- end_tests(agm_socket).

%   agm_sentinel(+Conn, +Agent, -Id): a watcher of the markers in the
%   registry of registerEventForAgent on Agent's model.

agm_sentinel(Conn, Agent, Id) :-
    oro_call(Conn, registerEventForAgent,
             [Agent, 'NEW_INSTANCE', 'ON_TRUE', m, '[?m rdf:type EvMarker]'],
             ok(Id)).

%   agm_marker(+Conn, +Agent, +Marker, -Event): add Marker to Agent's
%   model; Event is the next event, Id-Content (`timeout` if none
%   comes within 5 s).

agm_marker(Conn, Agent, Marker, Event) :-
    format(atom(Statement), '[~w rdf:type EvMarker]', [Marker]),
    oro_call(Conn, addForAgent, [Agent, Statement], ok(_)),
    oro_next_event(Conn, Event0, 5),
    (   Event0 = event(Id, Content)
    ->  Event = Id-Content
    ;   Event = Event0
    ).

%   agm_events_before(+Conn, +Sentinel, +First, -Events): First and the
%   events after it, up to the sentinel's firing (left out).

agm_events_before(Conn, Sentinel, First, Events) :-
    (   First = Sentinel-_
    ->  Events = []
    ;   First = _-_
    ->  Events = [First|Rest],
        oro_next_event(Conn, Event, 5),
        (   Event = event(Id, Content)
        ->  agm_events_before(Conn, Sentinel, Id-Content, Rest)
        ;   Rest = [Event]
        )
    ;   Events = [First]
    ).

agm_same(U, U2, Same) :-
    (   U2 == U
    ->  Same = same
    ;   Same = different(U2)
    ).

%   agm_event_not_found(+Id, -Reply): the EventNotFoundException reply
%   for Id.

agm_event_not_found(Id, error("laas.openrobots.ontology.exceptions.EventNotFoundException",
                              Message)) :-
    format(string(Message), "Event ~w does not exist in the model", [Id]).

agm_event_id(event(Id, _), Id) :-
    !.
agm_event_id(Other, Other).

agm_event_content(event(_, Content), Content) :-
    !.
agm_event_content(Other, Other).


                 /*******************************
                 *     REVISE OVER THE SOCKET   *
                 *******************************/

:- begin_tests(agm_socket_revise,
               [ setup(agm_start_commonsense),
                 cleanup(agm_stop)
               ]).

test(add_list, [ setup(agm_revise_fresh),
                 true(Reply-Where == ok("")-[true, false, false])
               ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": ["gerard", "nobody"]}'], Reply),
    agm_where_socket(Where).
test(add_string, [ setup(agm_revise_fresh),
                   true(Reply-Where == ok("")-[false, false, true])
                 ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": "toto"}'], Reply),
    agm_where_socket(Where).
test(add_all, [ setup(agm_revise_fresh),
                true(Reply-Where == ok("")-[true, true, true])
              ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": "all"}'], Reply),
    agm_where_socket(Where).
test(add_empty_list, [ setup(agm_revise_fresh),
                       true(Reply-Where == ok("")-[true, true, true])
                     ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": []}'], Reply),
    agm_where_socket(Where).
test(add_models_missing, [ setup(agm_revise_fresh),
                           true(Reply-Where == ok("")-[false, true, false])
                         ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add"}'], Reply),
    agm_where_socket(Where).
test(unknown_string_model_skipped,
     [ setup(agm_revise_fresh),
       true(Reply-Where == ok("")-[false, false, false])
     ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": "nobody"}'], Reply),
    agm_where_socket(Where).
test(safe_add, [ setup(agm_revise_fresh),
                 true(Reply-Where == ok("")-[true, true, false])
               ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "SAFE_ADD", "models": ["gerard", "ROBOT"]}'], Reply),
    agm_where_socket(Where).
test(retract, [ setup(agm_revise_fresh),
                true(Replies-Where == [ok(""), ok("")]-[false, true, true])
              ]) :-
    test_calls([ revise-['[r1 p o]', '{"method": "add", "models": "all"}'],
                 revise-['[r1 p o]', '{"method": "retract", "models": ["gerard"]}']
               ], Replies),
    agm_where_socket(Where).
test(update, [ setup(agm_revise_fresh),
               true(Replies-G-M == [ok(""), ok("")]-["false"]-["true"])
             ]) :-
    test_calls([ revise-['[ball isMoving true]', '{"method": "add", "models": "all"}'],
                 revise-['[ball isMoving false]', '{"method": "Update", "models": ["gerard"]}']
               ], Replies),
    test_set_call(findForAgent, [gerard, v, '[ball isMoving ?v]'], G),
    test_set_call(find, [v, '[ball isMoving ?v]'], M).
test(memory_profile, [ setup(agm_revise_fresh),
                       true(Reply-Found-Gone == ok("")-["r1"]-true)
                     ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": "gerard", "memory_profile": "shortterm"}'], Reply),
    test_set_call(findForAgent, [gerard, x, '[?x p o]'], Found),
    test_bool(test_wait_until(agm_forgotten_for(gerard, x, '[?x p o]'), 5), Gone).
test(revision, [ setup(agm_revise_fresh),
                 true(Name == "laas.openrobots.ontology.exceptions.NotImplementedException")
               ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "revision", "models": "all"}'], Reply),
    test_error_name(Reply, Name).
test(safe_update, [ setup(agm_revise_fresh),
                    true(Name == "laas.openrobots.ontology.exceptions.NotImplementedException")
                  ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "safe_update"}'], Reply),
    test_error_name(Reply, Name).
test(bad_method, [ setup(agm_revise_fresh),
                   true(Name-Where == "laas.openrobots.ontology.exceptions.InvalidPolicyException"-
                                      [false, false, false])
                 ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "insert", "models": "all"}'], Reply),
    test_error_name(Reply, Name),
    agm_where_socket(Where).
test(missing_method, [ setup(agm_revise_fresh),
                       true(Name == "laas.openrobots.ontology.exceptions.InvalidPolicyException")
                     ]) :-
    test_call(revise, ['[r1 p o]', '{"models": "all"}'], Reply),
    test_error_name(Reply, Name).
test(policy_not_json, [ setup(agm_revise_fresh),
                        true(Name == "laas.openrobots.ontology.exceptions.InvalidPolicyException")
                      ]) :-
    test_call(revise, ['[r1 p o]', 'add to all'], Reply),
    test_error_name(Reply, Name).
test(unknown_profile, [ setup(agm_revise_fresh),
                        true(Name-Where == "java.lang.IllegalArgumentException"-
                                           [false, false, false])
                      ]) :-
    test_call(revise, ['[r1 p o]', '{"method": "add", "models": "all", "memory_profile": "forever"}'], Reply),
    test_error_name(Reply, Name),
    agm_where_socket(Where).
test(bad_statement, [ setup(agm_revise_fresh),
                      true(Name-Where == "laas.openrobots.ontology.exceptions.IllegalStatementException"-
                                         [false, false, false])
                    ]) :-
    test_call(revise, ['[r1 p o, r2 p]', '{"method": "add", "models": "all"}'], Reply),
    test_error_name(Reply, Name),
    agm_where_socket(Where).

:- end_tests(agm_socket_revise).

%   agm_revise_fresh: a fresh server with the agents gerard and toto.

agm_revise_fresh :-
    agm_server_fresh,
    test_ok(add, ['[gerard rdf:type Human, toto rdf:type Agent]']),
    test_wait_until(( agm_agent_listed("gerard"),
                      agm_agent_listed("toto")
                    ), 5).

%   agm_where_socket(-Holds): whether `r1 p o` holds in gerard, myself
%   and toto.

agm_where_socket(Holds) :-
    maplist(agm_socket_holds('[?x p o]'), [gerard, myself, toto], Holds).

agm_socket_holds(Pattern, Agent, Bool) :-
    test_set_call(findForAgent, [Agent, x, Pattern], Xs),
    test_bool(memberchk("r1", Xs), Bool).


                 /*******************************
                 *        SESSION REPLAY        *
                 *******************************/

%   The robot session of April 2011, replayed against a server with the
%   robot id of that experiment and its human partner declared (see
%   test/fixtures/scenario-2011.ttl): every request must be answered,
%   and none with an error.

:- begin_tests(agm_replay,
               [ setup(agm_start_replay),
                 cleanup(agm_stop)
               ]).

test(robot_session_2011, true(Problems == [])) :-
    test_path('../../shared/workloads/robot-session-2011.log', Log),
    (   exists_file(Log)
    ->  agm_replay(Log, Problems)
    ;   format(user_error,
               "~NNotice: ~w not found: agent session replay skipped.~n",
               [Log]),
        Problems = []
    ).

:- end_tests(agm_replay).

agm_start_replay :-
    test_fixture('scenario-2011.ttl', Scenario),
    agm_start([ commonsense(true),
                ontology(Scenario),
                robot_id('JIDOKUKA_ROBOT')
              ]).

%   agm_replay(+Log, -Problems)
%
%   Replay every request of Log, one connection per `[thread N]`, in
%   log order, one at a time.  Problems are the lines that do not parse
%   and the requests whose answer is not ok: Line-Reply.

agm_replay(Log, Problems) :-
    read_file_to_string(Log, Text, [encoding(utf8)]),
    split_string(Text, "\n", "\r", Lines),
    convlist(agm_log_request, Lines, Requests),
    test_server_port(Port),
    call_cleanup(
        foldl(agm_replay_request(Port), Requests, Problems0, []),
        forall(retract(agm_replay_conn(_, Conn)),
               oro_disconnect(Conn))),
    Problems = Problems0,
    length(Requests, N),
    aggregate_all(count, member(_, Problems), NBad),
    format(user_error, "~Nagent replay: ~d requests, ~d not ok~n", [N, NBad]).

%   agm_log_request(+Line, -Request) is semidet: test_log_request/2,
%   a line without a `[thread N]` tag being bad(Line).

agm_log_request(Line, Request) :-
    test_log_request(Line, Request0),
    (   Request0 = request(_, "", _, _)
    ->  Request = bad(Line)
    ;   Request = Request0
    ).

agm_replay_request(_, bad(Line), [Line-unparsed|Problems], Problems) :-
    !.
agm_replay_request(Port, request(Line, Thread, Method, Params),
                   Problems0, Problems) :-
    (   agm_replay_conn(Thread, Conn)
    ->  true
    ;   oro_connect(Port, Conn),
        assertz(agm_replay_conn(Thread, Conn))
    ),
    oro_call(Conn, Method, Params, Reply, 30),
    (   Reply = ok(_)
    ->  Problems0 = Problems
    ;   Problems0 = [Line-Reply|Problems]
    ).
