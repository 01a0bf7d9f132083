:- module(oro_agents,
          [ oro_agents_start/0,
            oro_agents/1,               % -Names
            oro_create_agent/2,         % +Name, +Individual
            oro_revise/2                % +Statements, +Policy
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(debug)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/events/oro_events)).
:- use_module(library(oro/oro_knowledge)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/questions/oro_consistency)).

/** <module> Agent models: what other agents believe

The robot keeps a model of what each other agent believes (ORO's
"alterite" module, ORO-SPEC §8): a bottle can be on the table for the
robot and in the cupboard for the human.  A model is a set of graphs
(one per memory profile) over the shared, read-only ontology layer; facts
and schema added to one model never leak into another, and reasoning,
find, check, lookup, taxonomy and events all work per model.

A model is created for each individual that becomes an `Agent` in the
robot's model, asserted or inferred (`gerard rdf:type Human`), unless
it is the robot itself or the same as an agent that has one.  An
internal watcher (not affected by clearEvents) does it, inside the event
watcher thread; a request naming an agent whose creation is still
queued waits for it (see oro_store's resolve hook below).  In an
agent's model, `myself` is that agent (`myself owl:sameAs gerard`).
*/

:- dynamic agents_subscriber/1.

:- multifile oro_store:resolve_hook/1.

%   An agent created by a change that the watcher thread has not
%   processed yet is waited for, so that `add [gerard rdf:type Human]`
%   followed by `addForAgent gerard ...` works.  The watcher thread never
%   waits for itself.

oro_store:resolve_hook(_Name) :-
    \+ thread_self(oro_watcher),
    oro_events_sync.

%!  oro_agents_start is det.
%
%   Watch the robot's model for new agents, and create the models of
%   the agents it already knows.  Called by oro_init/1 and oro_reset/0.

oro_agents_start :-
    agent_subscriber(Subscriber),
    oro_register_event(myself, new_instance, on_true, a,
                       ["?a rdf:type oro:Agent"], Subscriber, _),
    rdf_equal(oro:'Agent', Agent),
    rdf_equal(rdf:type, Type),
    oro_find(myself, A, [rdf(A, Type, Agent)], Agents),
    new_agents(_, Agents).

agent_subscriber(Subscriber) :-
    (   agents_subscriber(Subscriber0)
    ->  Subscriber = Subscriber0
    ;   oro_subscriber_create(new_agents, Subscriber,
                              [registry(internal), in_watcher(true)]),
        assertz(agents_subscriber(Subscriber))
    ).

new_agents(_Id, Individuals) :-
    forall(member(X, Individuals), new_agent(X)).

new_agent(X) :-
    atom(X),
    \+ rdf_is_bnode(X),
    rdf_equal(oro:myself, Myself),
    \+ oro_same_individual(myself, X, Myself),
    \+ ( oro_same_individual(myself, X, Y),
         oro_iri_name(Y, Name),
         catch(oro_resolve_model_now(Name), _, fail)
       ),
    !,
    oro_iri_name(X, Name),
    oro_create_agent(Name, X).
new_agent(_).

oro_resolve_model_now(Name) :-
    (   oro_model(Name)
    ->  true
    ;   oro_model_alias(Name, _)
    ).

%!  oro_create_agent(+Name, +Individual) is det.
%
%   Create the model Name of the agent Individual (named as in
%   statements: `bob`, `oro:bob` or a full IRI): in it, `myself` is
%   Individual, and the robot (if it has an id) is a Robot.

oro_create_agent(Name, Individual0) :-
    must_be(atom, Name),
    must_be(nonvar, Individual0),
    oro_resource(Individual0, Individual),
    oro_create_model(Name),
    rdf_equal(oro:myself, Myself),
    rdf_equal(owl:sameAs, SameAs),
    oro_robot_id(RobotId),
    (   RobotId == ''
    ->  Facts = [rdf(Myself, SameAs, Individual)]
    ;   oro_name_iri(RobotId, Robot),
        rdf_equal(rdf:type, Type),
        rdf_equal(oro:'Robot', RobotClass),
        Facts = [rdf(Myself, SameAs, Individual), rdf(Robot, Type, RobotClass)]
    ),
    oro_add(Name, Facts),
    debug(oro(agents), 'Created the model of agent ~q', [Name]).

%!  oro_agents(-Names) is det.
%
%   Names are the ordered names of every model: `myself`, its aliases
%   (`default`, the robot id) and the agents.

oro_agents(Names) :-
    (   thread_self(oro_watcher)
    ->  true
    ;   oro_events_sync                     % agents still being created
    ),
    findall(N, ( oro_model(N) ; oro_model_alias(N, _) ), Names0),
    sort(Names0, Names).

%!  oro_revise(+Statements, +Policy) is det.
%
%   Apply Statements to the models a Policy dict selects (ORO's
%   revise(), ORO-SPEC §6.1):
%
%     - method: `add`, `safe_add`,
%       `retract` or `update` (any case); `revision` and
%       `safe_update` are not implemented;
%     - models: a model name or a list of them (unknown names are
%       skipped; `[]` is every model), `all` (every model); missing:
%       the robot's;
%     - memory_profile: for `add`, as oro_add/3.
%
%   @error domain_error(oro_revision_method, M) for a missing or unknown
%          method; existence_error(oro_revision_method, M) for the two
%          not implemented.
%   @error domain_error(oro_memory_profile, P) for an unknown profile.

oro_revise(Statements, Policy) :-
    must_be(list, Statements),
    must_be(dict, Policy),
    (   get_dict(method, Policy, Method0),
        text_lower(Method0, Method),
        memberchk(Method, [add, safe_add, retract, update, revision,
                           safe_update])
    ->  true
    ;   get_dict(method, Policy, Bad)
    ->  domain_error(oro_revision_method, Bad)
    ;   domain_error(oro_revision_method, '')
    ),
    (   memberchk(Method, [revision, safe_update])
    ->  existence_error(oro_revision_method, Method)
    ;   true
    ),
    revision_profile(Policy, Profile),
    revision_models(Policy, Models),
    oro_statements(Statements, _, _),               % reject a bad batch now
    forall(member(Model, Models),
           revise_model(Method, Model, Statements, Profile)).

revise_model(add, Model, Statements, Profile) :-
    oro_add(Model, Statements, Profile).
revise_model(safe_add, Model, Statements, Profile) :-
    oro_safe_add(Model, Statements, Profile, _).
revise_model(retract, Model, Statements, _) :-
    oro_remove(Model, Statements).
revise_model(update, Model, Statements, _) :-
    oro_update(Model, Statements).

revision_profile(Policy, Profile) :-
    (   get_dict(memory_profile, Policy, P0)
    ->  text_lower(P0, P),
        (   memberchk(P, [shortterm, episodic, longterm, default])
        ->  Profile = P
        ;   domain_error(oro_memory_profile, P0)
        )
    ;   Profile = longterm
    ).

revision_models(Policy, Models) :-
    (   get_dict(models, Policy, Spec)
    ->  true
    ;   Spec = myself
    ),
    (   is_list(Spec)
    ->  (   Spec == []
        ->  findall(M, oro_model(M), Models0)
        ;   findall(M, ( member(N0, Spec),
                         atom_string(N, N0),
                         catch(oro_resolve_model(N, M), _, fail)
                       ), Models0)
        )
    ;   text_lower(Spec, all)
    ->  findall(M, oro_model(M), Models0)
    ;   atom_string(N, Spec),
        (   catch(oro_resolve_model(N, M), _, fail)
        ->  Models0 = [M]
        ;   Models0 = []                    % unknown names are skipped
        )
    ),
    sort(Models0, Models).

text_lower(Text, Lower) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Lower).
