:- module(oro_setup,
          [ oro_init/1,                 % +Options
            oro_reset/0,
            oro_close/0
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_knowledge)).
:- use_module(library(oro/oro_memory)).
:- use_module(library(oro/oro_agents)).
:- use_module(library(oro/oro_save), []).
:- use_module(library(oro/events/oro_events)).

/** <module> Starting, resetting and closing the knowledge base

oro_init/1 builds the store from the ontologies (the common-sense one
unless told otherwise), attaches the journal of `--db`, starts the
watcher thread and creates the robot's model; oro_reset/0 forgets every
model and watcher but keeps the ontology layer; oro_close/0 flushes and
closes the journal.  This module sits above the knowledge operations
and the agents, which both build on the store it sets up.
*/

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.
:- (   user:file_search_path(oro_ontologies, oro_home(ontologies))
   ->  true
   ;   asserta(user:file_search_path(oro_ontologies, oro_home(ontologies)))
   ).

:- predicate_options(oro_init/1, 1,
                     [ commonsense(boolean),
                       ontologies(list(atom)),
                       time_base(positive_integer),
                       robot_id(atom),
                       save_dir(atom),
                       db(atom),
                       silent(boolean)
                     ]).

%!  oro_init(+Options) is det.
%
%   Start from an empty store: load the ontology layer and create the
%   robot model.  Options:
%
%     - commonsense(+Bool): load oro's common-sense ontology
%       (default `true`);
%     - ontologies(+Files): more ontology files (RDF/XML, Turtle or
%       N-Triples), loaded in order;
%     - robot_id(+Id): a synonym of `myself`;
%     - time_base(+MS): length of one memory time unit (default 1000);
%     - save_dir(+Dir): where oro_save/2 may write (default '': a
%       directory of the user's, see oro_save);
%     - db(+Dir): journal the models in Dir and restore what it holds
%       (see oro_persist): every change reported done survives a
%       crash.  Without it (the default) nothing is kept on disk;
%     - silent(+Bool): if `false`, report the progress of each ontology
%       load and its summary (see oro_load_ontology/2; default `true`).

oro_init(Options) :-
    must_be(list, Options),
    option(commonsense(CommonSense), Options, true),
    option(ontologies(Files), Options, []),
    option(robot_id(RobotId), Options, ''),
    option(save_dir(SaveDir), Options, ''),
    option(time_base(TimeBase), Options, 1000),
    option(db(Db), Options, ''),
    option(silent(Silent), Options, true),
    must_be(boolean, Silent),
    must_be(positive_integer, TimeBase),
    must_be(atom, Db),
    must_be(boolean, CommonSense),
    must_be(list(atom), Files),
    must_be(atom, RobotId),
    must_be(atom, SaveDir),
    (   catch(thread_property(oro_watcher, status(running)), _, fail)
    ->  oro_events_sync                     % no snapshot left in flight
    ;   true
    ),
    set_setting(oro_knowledge:robot_id, RobotId),
    set_setting(oro_save:save_dir, SaveDir),
    set_setting(oro_memory:time_base, TimeBase),
    oro_memory_reset,
    oro_store_detach,                       % the reset must not wipe it
    oro_store_reset,
    (   CommonSense == true
    ->  absolute_file_name(oro_ontologies('commonsense.ttl'), CS,
                           [access(read)]),
        oro_load_ontology(CS, [silent(Silent)])
    ;   true
    ),
    forall(member(File, Files),
           oro_load_ontology(File, [silent(Silent)])),
    (   Db == ''
    ->  true
    ;   oro_store_attach(Db)
    ),
    oro_events_start,
    oro_events_reset,
    oro_create_robot_model,
    oro_memory_restore,
    oro_agents_start.

%!  oro_close is det.
%
%   Close the database directory given to oro_init/1 (if any): wait for
%   the change in progress, flush and close the journals.  Later
%   changes are no longer kept on disk.  Called on a clean shutdown.

oro_close :-
    oro_store_detach.

%!  oro_reset is det.
%
%   Forget every model, agent, event watcher and fact asserted since
%   oro_init/1; the ontology layer stays as loaded.

oro_reset :-
    oro_events_reset,
    oro_memory_reset,
    oro_wipe_models,
    oro_create_robot_model,
    oro_agents_start.

